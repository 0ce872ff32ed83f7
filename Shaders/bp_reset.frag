// Step 1, per element: reset the elements flagged by the previous step or out
// of lifetime (Engine::stepElement, Engine::place). Writes the element state
// (lifetime, generation, placed now, 0), the element's release centre with
// whether it is hidden (outside the release window; Engine::place), its
// orientation quaternion (kept by shape matching; Along Flow turns it onto
// the flow sampled at the centre, Engine::alignToFlow) and its pose (the
// orientation, or the identity for one particle). Spins need nothing here:
// they are 0 until the pose pass writes every element's at the step's end.
uniform sampler2D bpElementState; // (lifetime, generation, flag, non-finite) after the last step
uniform sampler2D bpCenters;
uniform sampler2D bpOrientations;
uniform sampler2D bpPoses;
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
  if (1.0 + c < 1e-6)
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

layout(location = 0) out vec4 outState;
layout(location = 1) out vec4 outCenter;
layout(location = 2) out vec4 outOrientation;
layout(location = 3) out vec4 outPose;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e;
  if (!bpElementOf(texel, e))
  {
    outState = vec4(0.0);
    outCenter = vec4(0.0);
    outOrientation = vec4(0.0);
    outPose = vec4(0.0);
    return;
  }
  vec4 state = texelFetch(bpElementState, texel, 0);
  vec4 center = texelFetch(bpCenters, texel, 0);
  // A hidden element (placed outside the release window) is due at every step.
  bool hidden = center.w > 0.5;
  if (bpInitialize || state.z > 0.5 || state.x <= 0.0 || hidden)
  {
    float generation = bpInitialize ? 0.0 : state.y + 1.0;
    outState = vec4(bpLifetimeOf(e, generation), generation, 1.0, 0.0);
    outCenter = vec4(bpCenterOf(e, generation), bpReleasing ? 0.0 : 1.0);
    // A lattice point, or a weighted release none of whose candidates fits,
    // is not shown (Engine::place): due again at the next step.
    bool placedByBox = bpSeedCount == 0 && !bpLinked && (bpLattice || bpWeighted);
    outCenter.w = placedByBox && !bpSeedFits(outCenter.xyz) ? 1.0 : outCenter.w;
    outOrientation = bpFrameQuaternion;
    if (bpOrientation == 1 && bpPlaneAxis >= 0)
    {
      // A turn about the flat field's axis after the frame (inPlaneQuaternion).
      float turn = 3.14159265358979323846 * bpDraw(bpDrawElement(e), generation, 3u);
      vec4 r = vec4(0.0, 0.0, 0.0, cos(turn)); // half the angle
      r[bpPlaneAxis] = sin(turn);
      outOrientation = bpQuaternionProduct(r, bpFrameQuaternion);
    }
    else if (bpOrientation == 1)
    {
      // Shoemake's quaternion (quaternionFromUniforms).
      int d = bpDrawElement(e);
      float u1 = bpDraw(d, generation, 3u);
      float u2 = bpDraw(d, generation, 4u);
      float u3 = bpDraw(d, generation, 5u);
      float s1 = sqrt(1.0 - u1), s2 = sqrt(u1);
      float a = 6.28318530717958647692 * u2, b = 6.28318530717958647692 * u3;
      outOrientation = vec4(s1 * sin(a), s1 * cos(a), s2 * sin(b), s2 * cos(b));
    }
    else if (bpAlongFlow && !bpLinked)
    {
      // A super set keeps its lattice's one orientation (Engine::place).
      outOrientation = bpAlongFlowQuaternion(bpSample(outCenter.xyz, bpReleaseWeight));
    }
    // One particle has no orientation to show: its pose stays the identity.
    outPose = bpParticles > 1 ? outOrientation : vec4(0.0, 0.0, 0.0, 1.0);
  }
  else
  {
    outState = vec4(state.x, state.y, 0.0, 0.0);
    outCenter = center;
    outOrientation = texelFetch(bpOrientations, texel, 0);
    outPose = texelFetch(bpPoses, texel, 0);
  }
}
