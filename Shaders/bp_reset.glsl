// Step 1, per element: reset the elements flagged by the previous step or out
// of lifetime (Engine::stepElement, Engine::place). Writes the element state
// (lifetime, generation, placed now, 0), the element's release centre with
// whether it is hidden (outside the release window; Engine::place), its
// orientation quaternion (kept by shape matching; Along Flow turns it onto
// the flow sampled at the centre, Engine::alignToFlow) and its pose (the
// orientation, or the identity for one particle). Spins need nothing here:
// they are 0 until the pose pass writes every element's at the step's end.
uniform bool bpInitialize; // place every element as generation 0
uniform bool bpReleasing;  // the step overlaps the release window (releasesAt)
uniform vec4 bpFrameQuaternion;
uniform vec3 bpLongAxis;       // the template's long axis (longAxis in ElementTemplate.h)
uniform int bpPlaneAxis;       // Parameters::planeAxis
uniform bool bpAlongFlow;      // Orientation::AlongFlow, with a field to sample
uniform float bpReleaseWeight; // the second slice's weight at the step's start

// The template's long axis, as the frame leaves it, turned onto the flow v
// (alongFlowQuaternion).
vec4 bpAlongFlowQuaternion(vec3 v)
{
  vec3 d = v;
  if (bpPlaneAxis >= 0)
  {
    d[bpPlaneAxis] = 0.0;
  }
  float m = max(max(abs(d.x), abs(d.y)), abs(d.z));
  if (any(isnan(d)) || any(isinf(d)) || !(m > 0.0))
  {
    return bpFrameQuaternion;
  }
  d = vec3(d.x / m, d.y / m, d.z / m);
  float inverse = 1.0 / sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  d = vec3(d.x * inverse, d.y * inverse, d.z * inverse);
    vec3 a;
  a.x = bpFrameRow0.x * bpLongAxis.x + bpFrameRow0.y * bpLongAxis.y + bpFrameRow0.z * bpLongAxis.z;
  a.y = bpFrameRow1.x * bpLongAxis.x + bpFrameRow1.y * bpLongAxis.y + bpFrameRow1.z * bpLongAxis.z;
  a.z = bpFrameRow2.x * bpLongAxis.x + bpFrameRow2.y * bpLongAxis.y + bpFrameRow2.z * bpLongAxis.z;
  float c = a.x * d.x + a.y * d.y + a.z * d.z;
  vec4 r;
  if (1.0 + c < BP_ANTIPARALLEL_TOLERANCE)
  {
    r = vec4(bpFrameRow0.z, bpFrameRow1.z, bpFrameRow2.z, 0.0);
  }
  else
  {
    r = vec4(a.y * d.z - a.z * d.y, a.z * d.x - a.x * d.z, a.x * d.y - a.y * d.x, 1.0 + c);
    float n = 1.0 / sqrt(r.x * r.x + r.y * r.y + r.z * r.z + r.w * r.w);
    r = vec4(r.x * n, r.y * n, r.z * n, r.w * n);
  }
  return bpQuaternionProduct(r, bpFrameQuaternion);
}

// The orientation of element e placed as `generation` at `center`.
vec4 bpPlacedOrientation(int e, float generation, vec3 center)
{
  if (bpOrientation == BP_ORIENTATION_RANDOM && bpPlaneAxis >= 0)
  {
    // A turn about the flat field's axis after the frame (inPlaneQuaternion).
    float turn = BP_PI * bpDraw(bpDrawElement(e), generation, BP_ORIENTATION_DRAW);
    vec4 r = vec4(0.0, 0.0, 0.0, cos(turn)); // half the angle
    r[bpPlaneAxis] = sin(turn);
    return bpQuaternionProduct(r, bpFrameQuaternion);
  }
  if (bpOrientation == BP_ORIENTATION_RANDOM)
  {
    // Shoemake's quaternion (quaternionFromUniforms).
    int d = bpDrawElement(e);
    float u1 = bpDraw(d, generation, BP_ORIENTATION_DRAW);
    float u2 = bpDraw(d, generation, BP_ORIENTATION_DRAW + 1u);
    float u3 = bpDraw(d, generation, BP_ORIENTATION_DRAW + 2u);
    float s1 = sqrt(1.0 - u1), s2 = sqrt(u1);
    float a = (2.0 * BP_PI) * u2, b = (2.0 * BP_PI) * u3;
    return vec4(s1 * sin(a), s1 * cos(a), s2 * sin(b), s2 * cos(b));
  }
  if (bpAlongFlow && !bpLinked)
  {
    // A super set keeps its lattice's one orientation (Engine::place).
    return bpAlongFlowQuaternion(bpSample(center, bpReleaseWeight));
  }
  return bpFrameQuaternion;
}

// Element e's state (lifetime, generation, flag, non-finite), release centre,
// orientation and pose after the reset: placed anew where due.
void bpResetElement(int e, inout vec4 state, inout vec4 center, inout vec4 orientation,
  inout vec4 pose)
{
  // A hidden element (placed outside the release window: centre .w 1) is due
  // at every step. One terminated at the boundary (its test's flag 2, then
  // centre .w 2; Engine's Terminated) stays hidden, due only at the end of
  // its lifetime.
  bool hidden = center.w > 0.5 && center.w < 1.5;
  bool terminated = state.z > 1.5 || center.w > 1.5;
  if (!(bpInitialize || (state.z > 0.5 && state.z < 1.5) || state.x <= 0.0 || hidden))
  {
    state = vec4(state.x, state.y, 0.0, 0.0);
    center.w = terminated ? 2.0 : center.w;
    return;
  }
  float generation = bpInitialize ? 0.0 : state.y + 1.0;
  state = vec4(bpLifetimeOf(e, generation), generation, 1.0, 0.0);
  center = vec4(bpCenterOf(e, generation), bpReleasing ? 0.0 : 1.0);
    // A lattice point, or a weighted release none of whose candidates fits,
  // is not shown (Engine::place): due again at the next step.
  bool placedByBox = bpSeedCount == 0 && !bpLinked && (bpLattice || bpWeighted);
  center.w = placedByBox && !bpSeedFits(center.xyz) ? 1.0 : center.w;
  orientation = bpPlacedOrientation(e, generation, center.xyz);
  // One particle has no orientation to show: its pose stays the identity.
  pose = bpParticles > 1 ? orientation : vec4(0.0, 0.0, 0.0, 1.0);
}

void bpResetPass(ivec2 texel, int e, int i, inout vec4 state, inout vec4 center,
  inout vec4 orientation, inout vec4 pose)
{
  state = texelFetch(bpElementState, texel, 0);
  center = texelFetch(bpCenters, texel, 0);
  orientation = texelFetch(bpOrientations, texel, 0);
  pose = texelFetch(bpPoses, texel, 0);
  bpResetElement(e, state, center, orientation, pose);
}
