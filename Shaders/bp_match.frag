// Step 3 with shape matching, per element (Engine::matchShape): the centre of
// the particles and the rotation of the best rigid fit to the rest shape.
uniform sampler2D bpPositions;
uniform sampler2D bpRest;
uniform sampler2D bpOrientations;

layout(location = 0) out vec4 outCenter;
layout(location = 1) out vec4 outOrientation;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e = texel.y * bpElementGrid.x + texel.x;
  if (e >= bpElements)
  {
    outCenter = vec4(0.0);
    outOrientation = vec4(0.0);
    return;
  }
  vec3 c = vec3(0.0);
  for (int i = 0; i < bpParticles; ++i)
  {
    c += texelFetch(bpPositions, bpParticleTexel(e, i), 0).xyz;
  }
  c = c / float(bpParticles);
  vec3 a0 = vec3(0.0), a1 = vec3(0.0), a2 = vec3(0.0);
  for (int i = 0; i < bpParticles; ++i)
  {
    vec3 d = texelFetch(bpPositions, bpParticleTexel(e, i), 0).xyz - c;
    vec3 q = bpElementSize * texelFetch(bpRest, ivec2(i, 0), 0).xyz;
    a0 += d.x * q;
    a1 += d.y * q;
    a2 += d.z * q;
  }
  outCenter = vec4(c, 0.0);
  outOrientation = bpExtractRotation(a0, a1, a2, texelFetch(bpOrientations, texel, 0));
}
