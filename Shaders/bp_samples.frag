// For colouring, per particle: the velocity and |curl v| at the particle at
// the shown time, as bp::sampleAtPositions computes them (central differences
// one grid spacing either side, skipping flat axes).
uniform sampler2D bpState;
uniform float bpSampleWeight;
uniform vec3 bpSpacing;

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
  vec3 d[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0)); // d[a][k] = d v_k / d x_a
  for (int a = 0; a < 3; ++a)
  {
    if (bpDegenerate[a])
    {
      continue;
    }
    float h = bpSpacing[a];
    vec3 pp = p, pm = p;
    pp[a] += h;
    pm[a] -= h;
    d[a] = (bpSample(pp, bpSampleWeight) - bpSample(pm, bpSampleWeight)) / (2.0 * h);
  }
  float cx = d[1][2] - d[2][1];
  float cy = d[2][0] - d[0][2];
  float cz = d[0][1] - d[1][0];
  outSample = vec4(v, sqrt(cx * cx + cy * cy + cz * cz));
}
