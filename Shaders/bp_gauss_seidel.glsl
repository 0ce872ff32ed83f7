// Step 3 with Gauss-Seidel, per particle, one colour of springs (Engine::restore):
// springs of one colour share no particle, so each particle has at most one
// spring of this colour and takes its share of that spring's correction.
uniform sampler2D bpColouredSprings; // per (particle, colour): (a, b, share, valid), (rest, stiffness, 0, 0)
uniform int bpColour;

// Particle i of element e, at p, after the springs of `colour`.
vec3 bpGaussSeidelParticle(int e, int i, vec3 p, int colour)
{
  vec4 ends = texelFetch(bpColouredSprings, ivec2(2 * i, colour), 0);
  if (ends.w > 0.5)
  {
    vec4 spring = texelFetch(bpColouredSprings, ivec2(2 * i + 1, colour), 0);
    vec3 force;
    if (bpSpringForce(bpPositionOf(e, int(ends.x)), bpPositionOf(e, int(ends.y)), spring.x,
          spring.y, force))
    {
      p += ends.z * force;
    }
  }
  return p;
}

void bpGaussSeidelPass(ivec2 texel, int e, int i, inout vec4 position, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  position = vec4(bpGaussSeidelParticle(e, i, bpPositionOf(e, i), bpColour), 0.0);
}
