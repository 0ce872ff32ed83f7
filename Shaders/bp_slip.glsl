// Heavy particles (Core/Engine/Inertia.h; engine specification 2.2), per particle:
// the slip pass, after the reset and before advection, steps each
// particle's slip velocity and writes the displacement it adds to the
// tracer's (bp_advect.glsl reads it); the share pass, after the test, gives
// every particle of a restored element the element's mean slip (shareSlip),
// and 0 to an element whose positions turned non-finite.
uniform sampler2D bpSlips;     // per particle: the slip (xyz)
uniform sampler2D bpSlipsNext; // the share pass: the slip pass's
uniform vec3 bpSlipWeights;    // the second slice's weight at the step's start (x)
uniform float bpSlipDecay;     // InertiaStep: E, tau (1 - E), tau (h - tau (1 - E)), 1 - beta, g
uniform float bpSlipMemory;
uniform float bpSlipSettle;
uniform float bpSlipBuoyancy;
uniform vec3 bpSlipGravity;
uniform float bpTimeRate;      // 1 / (t1 - t0) of the field's slices; 0 when steady
uniform bool bpShareSlip;      // the element is restored (springs, shape matching or links)

// One slice's derivative along a direction in the cell at `a` with
// fractions f, the fractions moving at g = slope * q (Core/Field/
// TrilinearAlong.h: the interpolation's lerps carried with their derivative).
vec3 bpSliceAlong(sampler3D field, ivec3 a, vec3 f, vec3 g)
{
  vec3 c[8];
  bpCorners(field, a, c);
  vec3 step00 = c[1] - c[0], step10 = c[3] - c[2], step01 = c[5] - c[4], step11 = c[7] - c[6];
  vec3 x00 = c[0] + f.x * step00, x10 = c[2] + f.x * step10;
  vec3 x01 = c[4] + f.x * step01, x11 = c[6] + f.x * step11;
  vec3 across0 = x10 - x00, across1 = x11 - x01;
  vec3 y0 = x00 + f.y * across0, y1 = x01 + f.y * across1;
  vec3 d00 = g.x * step00, d10 = g.x * step10, d01 = g.x * step01, d11 = g.x * step11;
  vec3 e0 = (d00 + f.y * (d10 - d00)) + g.y * across0;
  vec3 e1 = (d01 + f.y * (d11 - d01)) + g.y * across1;
  return (e0 + f.z * (e1 - e0)) + g.z * (y1 - y0);
}

// VectorField::sampleAlong with a SlipStepper: u and du/dt at p, and the
// derivative (q . grad) u along q = (1 - beta) u + s, each slice's blended.
void bpSampleAlong(vec3 p, float weight, vec3 s, out vec3 u, out vec3 dudt, out vec3 along)
{
  vec3 f;
  ivec3 a = bpLocateCell(p, f);
  vec3 first = bpSampleSlice(bpField0, p);
  u = first;
  dudt = vec3(0.0);
  if (bpUnsteady)
  {
    vec3 second = bpSampleSlice(bpField1, p);
    u = first + weight * (second - first);
    dudt = (second - first) * bpTimeRate;
  }
  vec3 g = bpSlopes(a) * (bpSlipBuoyancy * u + s);
  along = bpSliceAlong(bpField0, a, f, g);
  if (bpUnsteady && weight > 0.0)
  {
    along += weight * (bpSliceAlong(bpField1, a, f, g) - along);
  }
}

// slipStep: the new slip and the displacement it adds, from the slip `s`.
void bpSlipStep(vec3 dudt, vec3 along, inout vec3 s, out vec3 move)
{
  vec3 a = bpSlipBuoyancy * (bpSlipGravity - dudt) - along;
  move = bpSlipMemory * s + bpSlipSettle * a;
  s = bpSlipDecay * s + bpSlipMemory * a;
}

// Particle i of an element whose state is `element` (z: placed in this step),
// at `p` before advection with slip `s`: its new slip and displacement.
void bpSlipParticle(int i, vec4 element, vec3 p, inout vec3 s, out vec3 move)
{
  move = vec3(0.0);
  if (element.z > 0.5)
  {
    s = vec3(0.0); // placed anew: released with the flow's velocity
  }
  if (bpPinned(i) || bpHeld(p, bpEndWeight))
  {
    return; // a particle Stick holds keeps its slip
  }
  vec3 u, dudt, along;
  bpSampleAlong(p, bpSlipWeights.x, s, u, dudt, along);
  bpSlipStep(dudt, along, s, move);
}

void bpSlipPass(ivec2 texel, int e, int i, inout vec4 slip, inout vec4 move,
  inout vec4 unused2, inout vec4 unused3)
{
  ivec2 at = bpElementTexel(e);
  vec4 element = texelFetch(bpElementState, at, 0);
  // Where the particle starts the step: placed anew (as bp_advect.glsl
  // places it) or where the last step left it.
  vec3 before = element.z > 0.5
    ? bpPlace(texelFetch(bpCenters, at, 0).xyz, texelFetch(bpOrientations, at, 0),
        texelFetch(bpRest, ivec2(i, 0), 0).xyz)
    : texelFetch(bpState, texel, 0).xyz;
  vec3 s = texelFetch(bpSlips, texel, 0).xyz, m;
  bpSlipParticle(i, element, before, s, m);
  slip = vec4(s, 0.0);
  move = vec4(m, 0.0);
}

// The slip pass's slip at a particle's texel with the walls' rule on its
// velocity (Engine::wallParticle), from what the advect pass wrote in the
// advected texture (its walled position, and in .w what the walls did).
// With Walls of the Surfaces (Stick, Slip, Bounce), where the advect pass wrote
// one met (the positions before's .w): the sides' rule where they left the
// particle (recomputed, bp_advect.glsl's bpWalledBySides, only where both
// met it), then the Wall's at its walled position (bpWallSlipOnSurfaces).
vec3 bpWalledBySides(ivec2 texel, int i, vec3 b);

vec3 bpWalledSlipOf(ivec2 texel, int i)
{
  vec3 s = texelFetch(bpSlipsNext, texel, 0).xyz;
  if (!bpWalled())
  {
    return s;
  }
  vec4 a = texelFetch(bpAdvected, texel, 0);
  vec4 b = bpWallsParticles() ? texelFetch(bpBefore, texel, 0) : vec4(0.0);
  int met = int(b.w);
  if (met == 0)
  {
    return bpWallSlip(int(a.w), a.xyz, s, bpEndWeight);
  }
  if (int(a.w) != 0)
  {
    s = bpWallSlip(int(a.w), bpWalledBySides(texel, i, b.xyz), s, bpEndWeight);
  }
  return bpWallSlipOnSurfaces(met, a.xyz, s, bpEndWeight);
}

// shareSlip, then a non-finite element's slips 0: particle i's slip after
// the step, reading its element's slips through `slipOf`.
void bpSlipSharePass(ivec2 texel, int e, int i, inout vec4 slip, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec4 element = texelFetch(bpElementState, bpElementTexel(e), 0);
  vec3 s = bpWalledSlipOf(texel, i);
  if (bpShareSlip && bpParticles > 1)
  {
    vec3 mean = vec3(0.0);
    for (int k = 0; k < bpParticles; ++k)
    {
      mean += bpWalledSlipOf(bpParticleTexel(e, k), k);
    }
    s = mean / float(bpParticles);
  }
  slip = vec4(element.w > 0.5 ? vec3(0.0) : s, 0.0);
}
