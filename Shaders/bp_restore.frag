// Step 3, per particle, one Jacobi iteration (Engine::restore): the sum of the
// corrections of the particle's springs, gathered in spring order, averaged
// (thesis §3.5) or scaled by the relaxation factor.
uniform sampler2D bpPositions;
uniform sampler2D bpParticleInfo;
uniform sampler2D bpSprings; // two texels per (particle, spring): (a, b, share, 0), (rest, stiffness, 0, 0)
uniform int bpSpringsWidth;  // texels per row, even
uniform bool bpAveraged;
uniform float bpRelaxation;

out vec4 outPosition;

vec4 entry(int k)
{
  return texelFetch(bpSprings, ivec2(k % bpSpringsWidth, k / bpSpringsWidth), 0);
}

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
  vec4 info = texelFetch(bpParticleInfo, ivec2(i, 0), 0);
  int first = int(info.x), count = int(info.y);
  vec3 acc = vec3(0.0);
  for (int k = first; k < first + count; ++k)
  {
    vec4 ends = entry(2 * k);
    vec4 spring = entry(2 * k + 1);
    vec3 pa = texelFetch(bpPositions, bpParticleTexel(e, int(ends.x)), 0).xyz;
    vec3 pb = texelFetch(bpPositions, bpParticleTexel(e, int(ends.y)), 0).xyz;
    vec3 d = pa - pb;
    float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (len > 0.0)
    {
      float f = spring.y * (spring.x - len) / len;
      acc += ends.z * (f * d);
    }
  }
  outPosition = vec4(bpAveraged ? p + acc * info.z : p + bpRelaxation * acc, 0.0);
}
