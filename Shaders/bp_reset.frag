// Step 1, per element: reset the elements flagged by the previous step or out
// of lifetime (Engine::stepElement, Engine::place). Writes the element state
// (lifetime, generation, placed now, 0), the element's release centre and its
// orientation quaternion (kept by shape matching).
uniform sampler2D bpElementState; // (lifetime, generation, flag, non-finite) after the last step
uniform sampler2D bpCenters;
uniform sampler2D bpOrientations;
uniform bool bpInitialize; // place every element as generation 0
uniform vec4 bpFrameQuaternion;

layout(location = 0) out vec4 outState;
layout(location = 1) out vec4 outCenter;
layout(location = 2) out vec4 outOrientation;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e = texel.y * bpElementGrid.x + texel.x;
  if (e >= bpElements)
  {
    outState = vec4(0.0);
    outCenter = vec4(0.0);
    outOrientation = vec4(0.0);
    return;
  }
  vec4 state = texelFetch(bpElementState, texel, 0);
  if (bpInitialize || state.z > 0.5 || state.x <= 0.0)
  {
    float generation = bpInitialize ? 0.0 : state.y + 1.0;
    outState = vec4(bpLifetimeOf(e, generation), generation, 1.0, 0.0);
    outCenter = vec4(bpCenterOf(e, generation), 0.0);
    outOrientation = bpFrameQuaternion;
    if (bpRandomOrientation)
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
  }
  else
  {
    outState = vec4(state.x, state.y, 0.0, 0.0);
    outCenter = texelFetch(bpCenters, texel, 0);
    outOrientation = texelFetch(bpOrientations, texel, 0);
  }
}
