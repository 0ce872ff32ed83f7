// Step 3, per particle, one Jacobi iteration (Engine::restore): the sum of the
// corrections of the particle's springs, gathered in spring order, averaged
// (thesis §3.5) or scaled by the relaxation factor.
uniform sampler2D bpSprings; // two texels per (particle, spring): (a, b, share, 0), (rest, stiffness, 0, 0)
uniform int bpSpringsWidth;  // texels per row, even
uniform bool bpAveraged;
uniform float bpRelaxation;

vec4 bpSpringEntry(int k)
{
  return texelFetch(bpSprings, ivec2(k % bpSpringsWidth, k / bpSpringsWidth), 0);
}

// The correction of one spring on particle (e, i), `share` its signed share.
vec3 bpSpringCorrection(int e, int a, int b, float share, float rest, float stiffness)
{
  vec3 force;
  return bpSpringForce(bpPositionOf(e, a), bpPositionOf(e, b), rest, stiffness, force)
    ? share * force
    : vec3(0.0);
}

#ifdef BP_GENERATED_SPRINGS
// The template's springs as code, one case per particle index (thesis §3.5):
// written by GpuTemplate from the template at configure time.
//BP::GeneratedSprings
#else
// The template's springs read from the spring buffer.
vec3 bpSpringSum(int e, int i, vec4 info)
{
  int first = int(info.x), count = int(info.y);
  vec3 acc = vec3(0.0);
  for (int k = first; k < first + count; ++k)
  {
    vec4 ends = bpSpringEntry(2 * k);
    vec4 spring = bpSpringEntry(2 * k + 1);
    acc += bpSpringCorrection(e, int(ends.x), int(ends.y), ends.z, spring.x, spring.y);
  }
  return acc;
}
#endif

// Particle i of element e, at p, after one Jacobi iteration.
vec3 bpJacobiParticle(int e, int i, vec3 p)
{
  vec4 info = texelFetch(bpParticleInfo, ivec2(i, 0), 0);
  vec3 acc = bpSpringSum(e, i, info);
  return bpAveraged ? p + acc * info.z : p + bpRelaxation * acc;
}

void bpRestorePass(ivec2 texel, int e, int i, inout vec4 position, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  position = vec4(bpJacobiParticle(e, i, bpPositionOf(e, i)), 0.0);
}
