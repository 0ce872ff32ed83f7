// For colouring, per particle: the velocity and |curl v| at the particle at
// the shown time, as bp::sampleAtPositions computes them: the curl of the
// trilinear interpolant in the cell that holds the particle
// (VectorField::sampleWithVorticity, the same operations in the same order).
uniform sampler2D bpState;
uniform float bpSampleWeight;

out vec4 outSample;

// d[a][k] = d v_k / d x_a in the cell at `a` (its first corner) with
// fractions f; w[a] is the fraction's derivative along axis a.
void bpGradient(sampler3D field, ivec3 a, vec3 f, vec3 w, out vec3 d[3])
{
  ivec3 s = bpNextCorner;
  vec3 c000 = texelFetch(field, a, 0).xyz;
  vec3 c100 = texelFetch(field, a + ivec3(s.x, 0, 0), 0).xyz;
  vec3 c010 = texelFetch(field, a + ivec3(0, s.y, 0), 0).xyz;
  vec3 c110 = texelFetch(field, a + ivec3(s.x, s.y, 0), 0).xyz;
  vec3 c001 = texelFetch(field, a + ivec3(0, 0, s.z), 0).xyz;
  vec3 c101 = texelFetch(field, a + ivec3(s.x, 0, s.z), 0).xyz;
  vec3 c011 = texelFetch(field, a + ivec3(0, s.y, s.z), 0).xyz;
  vec3 c111 = texelFetch(field, a + s, 0).xyz;
  vec3 x0 = (c100 - c000) + f.y * ((c110 - c010) - (c100 - c000));
  vec3 x1 = (c101 - c001) + f.y * ((c111 - c011) - (c101 - c001));
  d[0] = (x0 + f.z * (x1 - x0)) * w.x;
  vec3 y0 = (c010 - c000) + f.x * ((c110 - c100) - (c010 - c000));
  vec3 y1 = (c011 - c001) + f.x * ((c111 - c101) - (c011 - c001));
  d[1] = (y0 + f.z * (y1 - y0)) * w.y;
  vec3 z0 = (c001 - c000) + f.x * ((c101 - c100) - (c001 - c000));
  vec3 z1 = (c011 - c010) + f.x * ((c111 - c110) - (c011 - c010));
  d[2] = (z0 + f.y * (z1 - z0)) * w.z;
}

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
  ivec3 a;
  vec3 f, w;
  for (int k = 0; k < 3; ++k)
  {
    int cell;
    float fraction;
    bpLocate(k, p[k], cell, fraction);
    a[k] = cell;
    f[k] = fraction;
    // 0 along a flat axis (its inverse spacing is 0), where nothing varies.
    w[k] = bpRectilinear[k] ? texelFetch(bpAxes, ivec2(cell, k), 0).y : bpInverseSpacing[k];
  }
  vec3 d[3];
  bpGradient(bpField0, a, f, w, d);
  if (bpUnsteady && bpSampleWeight > 0.0)
  {
    vec3 d1[3];
    bpGradient(bpField1, a, f, w, d1);
    for (int k = 0; k < 3; ++k)
    {
      d[k] += bpSampleWeight * (d1[k] - d[k]);
    }
  }
  float cx = d[1][2] - d[2][1];
  float cy = d[2][0] - d[0][2];
  float cz = d[0][1] - d[1][0];
  outSample = vec4(v, sqrt(cx * cx + cy * cy + cz * cz));
}
