// Step 2, per particle: the particle's position before the step (placed anew
// for elements reset in this step) and after advection (Engine::advectParticle).
//
// A program with this kernel is compiled for one integrator (Gpu/GpuPasses.h,
// KernelSpecialisation): BP_INTEGRATOR is BP_INTEGRATOR_EULER, _RK2
// (midpoint) or _RK4, and BP_INERTIAL is defined for heavy particles.
#ifndef BP_INTEGRATOR
#error BP_INTEGRATOR is not defined: a program of this kernel is built for an integrator
#endif
uniform vec3 bpWeights; // second-slice weights at t, t + h/2, t + h
uniform bool bpPlaceOnly;

vec3 bpIntegrate(vec3 p)
{
  float h = bpStep;
  vec3 k1 = bpSample(p, bpWeights.x);
#if BP_INTEGRATOR == BP_INTEGRATOR_EULER
  return p + h * k1;
#elif BP_INTEGRATOR == BP_INTEGRATOR_RK2
  vec3 k2 = bpSample(p + 0.5 * h * k1, bpWeights.y);
  return p + h * k2;
#elif BP_INTEGRATOR == BP_INTEGRATOR_RK4
  vec3 k2 = bpSample(p + 0.5 * h * k1, bpWeights.y);
  vec3 k3 = bpSample(p + 0.5 * h * k2, bpWeights.y);
  vec3 k4 = bpSample(p + h * k3, bpWeights.z);
  return p + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
#else
#error BP_INTEGRATOR is none of BP_INTEGRATOR_EULER, _RK2 and _RK4
#endif
}

// Particle i of an element with state, centre and orientation after the
// reset, at `current` after the last step: where it starts the step
// (`before`) and where advection takes it.
void bpAdvectParticle(int i, vec4 element, vec4 center, vec4 orientation, vec3 current,
  out vec3 before, out vec3 advected)
{
  before = element.z > 0.5
    ? bpPlace(center.xyz, orientation, texelFetch(bpRest, ivec2(i, 0), 0).xyz)
    : current;
  // Stick holds a particle on a side of the box: not advected.
  advected = (bpPlaceOnly || bpPinned(i) || bpHeld(before, bpWeights.z)) ? before : bpIntegrate(before);
}

// Whether particle i, starting the step at `before`, meets the walls after
// advection (Engine::resetAndAdvect): a wall boundary, not placing only,
// neither pinned nor held.
bool bpMeetsWalls(int i, vec3 before)
{
  return bpWalled() && !bpPlaceOnly && !bpPinned(i) && !bpHeld(before, bpWeights.z);
}

void bpAdvectPass(ivec2 texel, int e, int i, inout vec4 advected, inout vec4 before,
  inout vec4 unused2, inout vec4 unused3)
{
  ivec2 at = bpElementTexel(e);
  vec3 b, a;
  bpAdvectParticle(i, texelFetch(bpElementState, at, 0), texelFetch(bpCenters, at, 0),
    texelFetch(bpOrientations, at, 0), texelFetch(bpState, texel, 0).xyz, b, a);
#ifdef BP_INERTIAL
  if (!bpPlaceOnly)
  {
    a += texelFetch(bpSlipMoves, texel, 0).xyz; // the slip's own (bp_slip.glsl)
  }
#endif
  // The walls (bp_common.glsl), what they did in .w for the slip share pass:
  // the field's sides' in the advected texture, the Surfaces' Wall met (its
  // index and side, 0 none) in the texture of the positions before.
  int hits = 0, met = 0;
  if (bpMeetsWalls(i, b))
  {
    hits = bpWallParticle(b, a, bpWeights.z);
    met = bpWallsParticles() ? bpWallOnSurfaces(b, a) : 0;
  }
  advected = vec4(a, float(hits));
  before = vec4(b, float(met));
}

// The slip share pass's: where the advect pass left particle i at `texel`
// (starting the step at `b`) before a Wall of the Surfaces moved it, the
// field's sides' walls done: its advection and the walls again.
vec3 bpWalledBySides(ivec2 texel, int i, vec3 b)
{
  vec3 a = bpIntegrate(b) + texelFetch(bpSlipMoves, texel, 0).xyz;
  bpWallParticle(b, a, bpWeights.z);
  return a;
}
