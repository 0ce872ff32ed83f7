// For colouring, per particle: the velocity and |curl v| at the particle at
// the shown time, as bp::sampleAtPositions computes them: the curl of the
// trilinear interpolant in the cell that holds the particle
// (VectorField::sampleWithVorticity, the same operations in the same order;
// bp_common.glsl: bpCurl).
uniform float bpSampleWeight;

void bpSamplesPass(ivec2 texel, int e, int i, inout vec4 sampled, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec3 p = texelFetch(bpState, texel, 0).xyz;
  vec3 v = bpSample(p, bpSampleWeight);
  vec3 c = bpCurl(p, bpSampleWeight);
  sampled = vec4(v, sqrt(c.x * c.x + c.y * c.y + c.z * c.z));
}
