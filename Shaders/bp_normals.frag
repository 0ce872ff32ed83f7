// Step 4, per particle: the normalised sum of the unit normals of the
// particle's triangles, gathered in triangle order (bp::elementNormals,
// bp_shared.glsl).
uniform sampler2D bpState;
uniform sampler2D bpParticleInfo;
uniform sampler2D bpTriangles;  // per (particle, triangle): (i0, i1, i2, 0)
uniform int bpTrianglesWidth;

out vec4 outNormal;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e, i;
  if (!bpParticleOf(texel, e, i))
  {
    outNormal = vec4(0.0);
    return;
  }
  vec4 info = texelFetch(bpParticleInfo, ivec2(i, 1), 0);
  int first = int(info.x), count = int(info.y);
  vec3 sum = vec3(0.0);
  for (int k = first; k < first + count; ++k)
  {
    vec4 tri = texelFetch(bpTriangles, ivec2(k % bpTrianglesWidth, k / bpTrianglesWidth), 0);
    vec3 a = texelFetch(bpState, bpParticleTexel(e, int(tri.x)), 0).xyz;
    vec3 b = texelFetch(bpState, bpParticleTexel(e, int(tri.y)), 0).xyz;
    vec3 c = texelFetch(bpState, bpParticleTexel(e, int(tri.z)), 0).xyz;
    bpAddTriangleNormal(sum, a, b, c);
  }
  outNormal = vec4(bpNormalOfSum(sum), 0.0);
}
