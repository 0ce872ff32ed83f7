// Step 2, per particle: the particle's position before the step (placed anew
// for elements reset in this step) and after advection (Engine::advectParticle).
uniform sampler2D bpState;        // positions (xyz) and force (w) after the last step
uniform sampler2D bpElementState; // after the reset pass
uniform sampler2D bpCenters;      // release centres, after the reset pass
uniform sampler2D bpOrientations; // release orientations, after the reset pass
uniform sampler2D bpRest;         // n x 1: template rest positions
uniform sampler2D bpParticleInfo; // n x 2: (spring offset, count, 1/degree, pinned), (triangle offset, count, 0, 0)
uniform int bpIntegrator;         // 0 Euler, 1 RK2 (midpoint), 2 RK4
uniform float bpStep;             // h
uniform vec3 bpWeights;           // second-slice weights at t, t + h/2, t + h
uniform bool bpPlaceOnly;

layout(location = 0) out vec4 outAdvected;
layout(location = 1) out vec4 outBefore;

vec3 integrate(vec3 p)
{
  float h = bpStep;
  vec3 k1 = bpSample(p, bpWeights.x);
  if (bpIntegrator == 0)
  {
    return p + h * k1;
  }
  if (bpIntegrator == 1)
  {
    vec3 k2 = bpSample(p + 0.5 * h * k1, bpWeights.y);
    return p + h * k2;
  }
  vec3 k2 = bpSample(p + 0.5 * h * k1, bpWeights.y);
  vec3 k3 = bpSample(p + 0.5 * h * k2, bpWeights.y);
  vec3 k4 = bpSample(p + h * k3, bpWeights.z);
  return p + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

void main()
{
  int e, i;
  if (!bpParticleOf(ivec2(gl_FragCoord.xy), e, i))
  {
    outAdvected = vec4(0.0);
    outBefore = vec4(0.0);
    return;
  }
  vec4 element = texelFetch(bpElementState, bpElementTexel(e), 0);
  vec3 p = element.z > 0.5
    ? bpPlace(texelFetch(bpCenters, bpElementTexel(e), 0).xyz,
        texelFetch(bpOrientations, bpElementTexel(e), 0), texelFetch(bpRest, ivec2(i, 0), 0).xyz)
    : texelFetch(bpState, ivec2(gl_FragCoord.xy), 0).xyz;
  outBefore = vec4(p, 0.0);
  bool pinned = texelFetch(bpParticleInfo, ivec2(i, 0), 0).w > 0.5;
  outAdvected = vec4((bpPlaceOnly || pinned) ? p : integrate(p), 0.0);
}
