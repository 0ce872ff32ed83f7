// Step 3 of a super set, per particle, after each restoration iteration
// (Engine::restoreLinks): one averaged Jacobi pass over the links that join
// particle i of an element to particle i of its lattice neighbours.
uniform sampler2D bpPositions;
uniform sampler2D bpParticleInfo;
uniform isampler2D bpLinkNeighbours; // per element: +u, -u, +v, -v; -1 where none
uniform sampler2D bpLinkRest;        // per element: the rest length of each
uniform float bpLinkStiffness;

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
  vec3 q = texelFetch(bpPositions, texel, 0).xyz;
  if (texelFetch(bpParticleInfo, ivec2(i, 0), 0).w > 0.5)
  {
    outPosition = vec4(q, 0.0);
    return;
  }
  ivec4 neighbour = texelFetch(bpLinkNeighbours, bpElementTexel(e), 0);
  vec4 rest = texelFetch(bpLinkRest, bpElementTexel(e), 0);
  vec3 acc = vec3(0.0);
  int count = 0;
  for (int d = 0; d < 4; ++d)
  {
    if (neighbour[d] < 0)
    {
      continue;
    }
    ++count;
    vec3 o = texelFetch(bpPositions, bpParticleTexel(neighbour[d], i), 0).xyz;
    vec3 force;
    if (bpSpringForce(q, o, rest[d], bpLinkStiffness, force))
    {
      acc += 0.5 * force;
    }
  }
  if (count > 0)
  {
    float average = 1.0 / float(count);
    q = q + acc * average;
  }
  outPosition = vec4(q, 0.0);
}
