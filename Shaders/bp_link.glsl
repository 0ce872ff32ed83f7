// Step 3 of a super set, per particle, after each restoration iteration
// (Engine::restoreLinks): one averaged Jacobi pass over the links that join
// particle i of an element to particle i of its lattice neighbours. It reads
// other elements' particles, so it is a pass of its own on both paths.
uniform isampler2D bpLinkNeighbours; // per element: +u, -u, +v, -v; -1 where none
uniform sampler2D bpLinkRest;        // per element: the rest length of each
uniform float bpLinkStiffness;

void bpLinkPass(ivec2 texel, int e, int i, inout vec4 position, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec3 q = bpPositionOf(e, i);
  if (bpPinned(i))
  {
    position = vec4(q, 0.0);
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
    vec3 force;
    if (bpSpringForce(q, bpPositionOf(neighbour[d], i), rest[d], bpLinkStiffness, force))
    {
      acc += 0.5 * force;
    }
  }
  if (count > 0)
  {
    float average = 1.0 / float(count);
    q = q + acc * average;
  }
  position = vec4(q, 0.0);
}
