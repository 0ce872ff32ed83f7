// Step 1, per element: reset the elements flagged by the previous step or out
// of lifetime (Engine::stepElement, Engine::place). Writes the element state
// (lifetime, generation, placed now, 0) and the element's release centre.
uniform sampler2D bpElementState; // (lifetime, generation, flag, non-finite) after the last step
uniform sampler2D bpCenters;
uniform bool bpInitialize; // place every element as generation 0

layout(location = 0) out vec4 outState;
layout(location = 1) out vec4 outCenter;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e = texel.y * bpElementGrid.x + texel.x;
  if (e >= bpElements)
  {
    outState = vec4(0.0);
    outCenter = vec4(0.0);
    return;
  }
  vec4 state = texelFetch(bpElementState, texel, 0);
  if (bpInitialize || state.z > 0.5 || state.x <= 0.0)
  {
    float generation = bpInitialize ? 0.0 : state.y + 1.0;
    outState = vec4(bpLifetimeOf(e, generation), generation, 1.0, 0.0);
    outCenter = vec4(bpCenterOf(e, generation), 0.0);
  }
  else
  {
    outState = vec4(state.x, state.y, 0.0, 0.0);
    outCenter = texelFetch(bpCenters, texel, 0);
  }
}
