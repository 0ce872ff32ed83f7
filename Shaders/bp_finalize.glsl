// Step 5, per particle: the new state. A non-finite element keeps its
// positions from before the step (so nothing non-finite is ever drawn); the
// force is the length of the restoration displacement.
uniform sampler2D bpRestored;
uniform sampler2D bpShifts; // per element, from the test pass (anchored or periodic only)

// A particle's state after the step (position, force) from its positions
// before the step, after advection and after restoration, its element's
// state after the test and, anchored (bpAnchored), its move to the anchor.
vec4 bpFinalParticle(vec3 restored, vec3 advected, vec3 before, vec4 element, vec4 shift)
{
  if (element.w > 0.5)
  {
    return vec4(before, 0.0);
  }
  vec3 q = restored;
  vec3 d = q - advected;
  if (bpAnchored || bpShiftsPeriodic)
  {
    // The force stays the restoration's: it is taken before the move.
    q += shift.xyz;
  }
  return vec4(q, sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
}

void bpFinalizePass(ivec2 texel, int e, int i, inout vec4 state, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  ivec2 at = bpElementTexel(e);
  state = bpFinalParticle(texelFetch(bpRestored, texel, 0).xyz,
    texelFetch(bpAdvected, texel, 0).xyz, texelFetch(bpBefore, texel, 0).xyz,
    texelFetch(bpElementState, at, 0), texelFetch(bpShifts, at, 0));
}

// Engine::wallAfterRestoration, a pass of its own after the last restoration
// pass (Boundary Stick, Slip or Bounce): each particle's restored position
// (bpPositions) kept in the box and out of cells outside the flow, or back at
// its walled advected position where Stick holds it; then kept off the
// Surfaces' Walls (Engine::keepOffSurfaceWalls).
void bpWallPass(ivec2 texel, int e, int i, inout vec4 walled, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec3 a = texelFetch(bpAdvected, texel, 0).xyz;
  vec3 q = bpWallRestored(texelFetch(bpPositions, texel, 0).xyz, a, bpEndWeight);
  // The Surfaces' Walls (Stick, Slip, Bounce): restoration takes no particle
  // through one (a particle Stick holds on one is back at a above).
  walled = vec4(bpWallsParticles() ? bpWallRestoredOnSurfaces(q, a) : q, 0.0);
}
