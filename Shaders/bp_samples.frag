// For colouring, per particle: the velocity and |curl v| at the particle at
// the shown time, as bp::sampleAtPositions computes them: the curl of the
// trilinear interpolant in the cell that holds the particle
// (VectorField::sampleWithVorticity, the same operations in the same order;
// bp_common.glsl: bpCurl).
uniform sampler2D bpState;
uniform float bpSampleWeight;

out vec4 outSample;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e, i;
  if (!bpParticleOf(texel, e, i))
  {
    outSample = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(bpState, texel, 0).xyz;
  vec3 v = bpSample(p, bpSampleWeight);
  vec3 c = bpCurl(p, bpSampleWeight);
  outSample = vec4(v, sqrt(c.x * c.x + c.y * c.y + c.z * c.z));
}
