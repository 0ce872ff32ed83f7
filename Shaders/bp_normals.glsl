// Step 4, per particle: the normalised sum of the unit normals of the
// particle's triangles, gathered in triangle order (bp::elementNormals,
// bp_shared.glsl).
uniform sampler2D bpTriangles; // per (particle, triangle): (i0, i1, i2, 0)
uniform int bpTrianglesWidth;

void bpNormalsPass(ivec2 texel, int e, int i, inout vec4 normal, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec4 info = texelFetch(bpParticleInfo, ivec2(i, 1), 0);
  int first = int(info.x), count = int(info.y);
  vec3 sum = vec3(0.0);
  for (int k = first; k < first + count; ++k)
  {
    vec4 tri = texelFetch(bpTriangles, ivec2(k % bpTrianglesWidth, k / bpTrianglesWidth), 0);
    bpAddTriangleNormal(sum, bpPositionOf(e, int(tri.x)), bpPositionOf(e, int(tri.y)),
      bpPositionOf(e, int(tri.z)));
  }
  normal = vec4(bpNormalOfSum(sum), 0.0);
}
