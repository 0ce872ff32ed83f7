// Step 3 with Gauss-Seidel, per particle, one colour of springs (Engine::restore):
// springs of one colour share no particle, so each particle has at most one
// spring of this colour and takes its share of that spring's correction.
uniform sampler2D bpPositions;
uniform sampler2D bpColouredSprings; // per (particle, colour): (a, b, share, valid), (rest, stiffness, 0, 0)
uniform int bpColour;

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
  vec4 ends = texelFetch(bpColouredSprings, ivec2(2 * i, bpColour), 0);
  if (ends.w > 0.5)
  {
    vec4 spring = texelFetch(bpColouredSprings, ivec2(2 * i + 1, bpColour), 0);
    vec3 pa = texelFetch(bpPositions, bpParticleTexel(e, int(ends.x)), 0).xyz;
    vec3 pb = texelFetch(bpPositions, bpParticleTexel(e, int(ends.y)), 0).xyz;
    vec3 force;
    if (bpSpringForce(pa, pb, spring.x, spring.y, force))
    {
      p += ends.z * force;
    }
  }
  outPosition = vec4(p, 0.0);
}
