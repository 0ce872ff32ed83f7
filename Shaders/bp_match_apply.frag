// Step 3 with shape matching, per particle: move towards the goal, the rest
// position turned by the fitted rotation about the centre; pinned ones stay.
uniform sampler2D bpPositions;
uniform sampler2D bpRest;
uniform sampler2D bpParticleInfo;
uniform sampler2D bpMatchCenters;
uniform sampler2D bpOrientations; // after the fit
uniform float bpShapeStiffness;
uniform bool bpLinearMatching;
uniform sampler2D bpMatchLinear0; // the linear mode's goal matrix, packed (bp_match.frag)
uniform sampler2D bpMatchLinear1;

out vec4 outPosition;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e, i;
  if (!bpParticleOf(texel, e, i))
  {
    outPosition = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(bpPositions, texel, 0).xyz;
  if (texelFetch(bpParticleInfo, ivec2(i, 0), 0).w > 0.5)
  {
    outPosition = vec4(p, 0.0);
    return;
  }
  vec4 fit = texelFetch(bpMatchCenters, bpElementTexel(e), 0);
  vec3 c = fit.xyz;
  vec3 r0, r1, r2;
  if (bpLinearMatching)
  {
    vec4 l0 = texelFetch(bpMatchLinear0, bpElementTexel(e), 0);
    vec4 l1 = texelFetch(bpMatchLinear1, bpElementTexel(e), 0);
    r0 = vec3(fit.w, l0.x, l0.y);
    r1 = vec3(l0.z, l0.w, l1.x);
    r2 = vec3(l1.y, l1.z, l1.w);
  }
  else
  {
    bpQuaternionRows(texelFetch(bpOrientations, bpElementTexel(e), 0), r0, r1, r2);
  }
  vec3 q = bpElementSize * texelFetch(bpRest, ivec2(i, 0), 0).xyz;
  vec3 goal = c + bpRowsTimes(r0, r1, r2, q);
  outPosition = vec4(p + bpShapeStiffness * (goal - p), 0.0);
}
