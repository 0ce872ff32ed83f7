// Step 5, per element: the reposition test (Engine::settle): flag the
// element when its centre (or any particle) left the field or entered a cell
// outside the flow's domain, when in its first step its centre moved slower
// than the release speed, or when a position is not finite; and take the
// step off its lifetime. With Boundary Terminate (bpBoundary) an element that
// left the field is flagged 2 instead of 1 (Engine::settle's Terminated): the
// reset keeps it hidden (centre .w 2) until its lifetime runs out. An
// element whose centre's step crosses an Outlet of the Surfaces input is
// flagged 2 as well (Engine::flagAfterStep, engine specification 2.10).
uniform bool bpAnyParticle;
uniform float bpReleaseMinSpeed; // 0: every release stays
uniform bool bpSettleOnly; // after initialisation: clear the placed-now mark, test nothing
// Anchor = Centre (bpAnchored): the element is tested where it is moved back
// to, its release centre, and the move is written for the finalize pass.

// Engine::releasedStagnant: `released`, the element's release centre.
bool bpReleasedStagnant(int e, vec4 state, vec3 c, vec3 released)
{
  if (!(bpReleaseMinSpeed > 0.0) || bpLinked)
  {
    return false;
  }
  vec3 d = c - released;
  float reach = bpReleaseMinSpeed * bpStep;
  return dot(d, d) < reach * reach && bpLifetimeOf(e, state.y) - state.x < 0.5 * bpStep;
}

// The Surfaces' Outlet triangles (engine specification 2.10; gates change
// nothing in a step and are not here): bpOutletCount of them, 0 where there
// are none (then nothing here is read). Corner c of triangle k is texel
// (3 (k % BP_OUTLET_ROW) + c, k / BP_OUTLET_ROW) of bpOutlets.
uniform int bpOutletCount;
uniform sampler2D bpOutlets;

vec3 bpOutletCorner(int k, int c)
{
  return texelFetch(bpOutlets, ivec2(3 * (k % BP_OUTLET_ROW) + c, k / BP_OUTLET_ROW), 0).xyz;
}

// Where the step a + t d of an element's centre meets Outlet triangle k
// (bp_common.glsl: bpMeetTriangle).
float bpMeetOutlet(int k, vec3 a, vec3 d)
{
  return bpMeetTriangle(bpOutletCorner(k, 0), bpOutletCorner(k, 1), bpOutletCorner(k, 2), a, d);
}

// Whether the step a -> b of an element's centre crosses an Outlet
// triangle. Any crossing ends the element, so the first triangle met will do.
bool bpCrossesOutlet(vec3 a, vec3 b)
{
  vec3 d = b - a;
  for (int k = 0; k < bpOutletCount; ++k)
  {
    if (bpMeetOutlet(k, a, d) > 0.0)
    {
      return true;
    }
  }
  return false;
}

// SurfaceSet::passages' seam (engine specification 2.8, 2.10): whether the
// point p of a crossing lies within the box (closed) along each axis the
// periodic shift `seam` moves the element by.
bool bpWithinSeam(vec3 p, vec3 seam)
{
  for (int a = 0; a < 3; ++a)
  {
    if (seam[a] != 0.0 && !(p[a] >= bpLower[a] && p[a] <= bpUpper[a]))
    {
      return false;
    }
  }
  return true;
}

// The part of `seam` that `part` picks (bit a: axis a) in s; false where it
// picks an axis the seam does not move. Part 0 is the step itself.
bool bpSeamPart(vec3 seam, int part, out vec3 s)
{
  s = vec3(0.0);
  for (int a = 0; a < 3; ++a)
  {
    if ((part & (1 << a)) != 0)
    {
      if (seam[a] == 0.0)
      {
        return false;
      }
      s[a] = seam[a];
    }
  }
  return true;
}

// The smallest t of the step a -> b's crossings with the Outlets, 2 where
// it crosses none: whether it passes an Outlet or a Wall first. With a
// `seam` (not 0: the centre left through a periodic side) the step
// translated by each part of it is tested too, and of each only the
// crossings within the box along the seam's axes count (t the share of the
// whole step): SurfaceSet::passages.
float bpFirstOutletCrossing(vec3 a, vec3 b, vec3 seam)
{
  bool across = seam != vec3(0.0);
  float best = 2.0;
  for (int part = 0; part < (across ? 8 : 1); ++part)
  {
    vec3 s;
    if (!bpSeamPart(seam, part, s))
    {
      continue;
    }
    vec3 from = a + s, d = (b + s) - from;
    for (int k = 0; k < bpOutletCount; ++k)
    {
      float t = bpMeetOutlet(k, from, d);
      t = across && t > 0.0 && !bpWithinSeam(from + t * d, seam) ? -1.0 : t;
      best = t > 0.0 && t < best ? t : best;
    }
  }
  return best;
}

// bpFirstWallCrossing of the step a -> b across a `seam` that is not 0, as
// bpFirstOutletCrossing: the step and its translates, the crossings within
// the box along the seam's axes.
float bpFirstWallAcross(vec3 a, vec3 b, vec3 seam, out int first)
{
  first = -1;
  float best = 2.0;
  if (!bpFinite(a) || !bpFinite(b))
  {
    return best;
  }
  for (int part = 0; part < 8; ++part)
  {
    vec3 s;
    if (!bpSeamPart(seam, part, s))
    {
      continue;
    }
    vec3 from = a + s, d = (b + s) - from;
    for (int k = 0; k < bpWallCount; ++k)
    {
      float t = bpMeetWall(k, from, d);
      if (t > 0.0 && t < best && bpWithinSeam(from + t * d, seam))
      {
        best = t;
        first = k;
      }
    }
  }
  return best;
}

// Whether the test reads each element's centre before the step (`from`):
// with Outlets, or with Walls that end elements (Boundary Release Again or
// Terminate; with Slip or Bounce they act on the particles, bp_common.glsl).
bool bpTestsPassages()
{
  return bpOutletCount > 0 || (bpWallCount > 0 && !bpWalled());
}

// Engine::passSurfaces' flag for an element whose centre went a -> b: 2
// (terminated) where the first Outlet or Wall it passes is an Outlet, or a
// Wall with Terminate; 1 (due) where it is a Wall with Release Again; else 0.
// `seam`: the periodic shift the element moves by after the step (0: none).
float bpPassageFlag(vec3 a, vec3 b, vec3 seam)
{
  bool across = seam != vec3(0.0);
  if (bpWallCount == 0 || bpWalled())
  {
    bool crosses = across ? bpFirstOutletCrossing(a, b, seam) <= 1.0 : bpCrossesOutlet(a, b);
    return bpOutletCount > 0 && crosses ? 2.0 : 0.0;
  }
  int k;
  float wall = across ? bpFirstWallAcross(a, b, seam, k) : bpFirstWallCrossing(a, b, k);
  float outlet = bpOutletCount > 0 ? bpFirstOutletCrossing(a, b, seam) : 2.0;
  if (outlet <= 1.0 && outlet <= wall)
  {
    return 2.0;
  }
  return k < 0 ? 0.0 : bpBoundary == BP_BOUNDARY_RELEASE_AGAIN ? 1.0 : 2.0;
}

// Element e with its state after the reset and its release centre, its
// particles restored (bpPositionOf), and with Outlets (bpOutletCount > 0)
// `from`, its particles' mean before the step (summed in float, as the
// centre below): its state after the test (lifetime, generation, flag,
// non-finite) and, anchored, its move to the anchor.
void bpTestElement(int e, vec4 state, vec4 center, vec3 from, out vec4 tested, out vec4 shift)
{
  shift = vec4(0.0);
  vec3 seam = vec3(0.0); // the periodic shift alone (not the anchor's move)
  if (bpSettleOnly)
  {
    tested = vec4(state.x, state.y, 0.0, 0.0);
    return;
  }
  vec3 c = vec3(0.0);
  bool finite = true, anyOutside = false;
  for (int i = 0; i < bpParticles; ++i)
  {
    vec3 q = bpPositionOf(e, i);
    finite = finite && bpFinite(q);
    c += q;
    anyOutside = anyOutside || !bpInDomain(q, bpEndWeight);
  }
  c /= float(bpParticles);
  vec3 at = c;
  if (bpAnchored)
  {
    // Engine::anchor: every particle moved by the release centre minus the
    // mean; the release-speed test below still reads the mean the flow gave.
    at = center.xyz;
    shift = vec4(at - c, 0.0);
    anyOutside = false;
    for (int i = 0; bpAnyParticle && i < bpParticles; ++i)
    {
      vec3 q = bpPositionOf(e, i) + shift.xyz;
      anyOutside = anyOutside || !bpInDomain(q, bpEndWeight);
    }
  }
  else if (finite && any(bpPeriodic))
  {
    // Engine::wrapPeriodic: a centre beyond a periodic side moves the whole
    // element by whole periods (Periodic.h); finalize applies the shift.
    shift = vec4(bpPeriodicShift(c), 0.0);
    seam = shift.xyz;
    if (shift.xyz != vec3(0.0))
    {
      at = c + shift.xyz;
      anyOutside = false;
      for (int i = 0; bpAnyParticle && i < bpParticles; ++i)
      {
        vec3 q = bpPositionOf(e, i) + shift.xyz;
        anyOutside = anyOutside || !bpInDomain(q, bpEndWeight);
      }
    }
  }
  bool left = bpAnyParticle ? anyOutside : !bpInDomain(at, bpEndWeight);
  bool due = !finite || bpReleasedStagnant(e, state, c, center.xyz);
  // The Outlets: an element shown (centre .w 0: not hidden by the release
  // window, not terminated), finite and not due, whose centre's step (before
  // any periodic move, and across the seam where it moves: bpPassageFlag)
  // crosses one ends there; that wins over leaving.
  // With Release Again or Terminate a Wall ends it too (flagged 1 or 2, as
  // the field's sides do), where it passes the Wall before any Outlet.
  float ended = bpTestsPassages() && !due && center.w < 0.5 && !bpLinked && bpFinite(from)
    ? bpPassageFlag(from, c, seam)
    : 0.0;
  // A super set's element stays (finalize keeps its last good positions):
  // resetting it alone would tear the structure. A terminated element
  // (centre .w 2) stays terminated until its lifetime runs out.
  float flag = 0.0;
  if (!bpLinked && !(center.w > 1.5))
  {
    // A wall (Stick, Slip, Bounce) keeps the element in: never reset for leaving.
    flag = due || (left && !bpWalled()) ? 1.0 : 0.0;
    flag = (left && !due && bpBoundary == BP_BOUNDARY_TERMINATE) ? 2.0 : flag;
    flag = ended > 0.0 ? ended : flag;
  }
  tested = vec4(state.x - bpStep, state.y, flag, finite ? 0.0 : 1.0);
}

void bpTestPass(ivec2 texel, int e, int i, inout vec4 tested, inout vec4 shift,
  inout vec4 unused2, inout vec4 unused3)
{
  // The centre before the step, from the advect pass's positions before it
  // (bpBefore), for the Outlets and Walls only.
  vec3 from = vec3(0.0);
  for (int i = 0; bpTestsPassages() && i < bpParticles; ++i)
  {
    from += texelFetch(bpBefore, bpParticleTexel(e, i), 0).xyz;
  }
  from /= float(bpParticles);
  bpTestElement(e, texelFetch(bpElementState, texel, 0), texelFetch(bpCenters, texel, 0), from,
    tested, shift);
}
