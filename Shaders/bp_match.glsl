// Step 3 with shape matching (Engine::matchShape), in two kernels.
// Per element, the fit: the centre of the particles and their moment
// (bpMomentOf), and the rotation of the best rigid fit to the rest shape; in
// the linear mode also the goal matrix M = beta * A Aqq^-1 + (1 - beta) * R,
// packed row by row into fit.w, linear0 and linear1.
// Per particle, the move towards the goal: the rest position turned by the
// fit about the centre; pinned ones stay.
uniform float bpLinearBlend;       // beta
uniform vec3 bpRestMomentInverse0; // rows of Aqq^-1 (restMomentInverse)
uniform vec3 bpRestMomentInverse1;
uniform vec3 bpRestMomentInverse2;
uniform float bpShapeStiffness;
// The fit, per element, for the move's own pass.
uniform sampler2D bpMatchCenters;
uniform sampler2D bpMatchLinear0;
uniform sampler2D bpMatchLinear1;

// Element e's fit; `orientation`, its kept rotation, becomes the fitted one.
void bpMatchElement(int e, inout vec4 orientation, out vec4 fit, out vec4 linear0,
  out vec4 linear1)
{
  linear0 = vec4(0.0);
  linear1 = vec4(0.0);
  vec3 c, a0, a1, a2;
  bpMomentOf(e, c, a0, a1, a2);
  fit = vec4(c, 0.0);
  orientation = bpFitRotation(a0, a1, a2, orientation, BP_MATCH_ITERATIONS);
  if (bpLinearMatching)
  {
    vec3 r[3];
    bpQuaternionRows(orientation, r[0], r[1], r[2]);
    vec3 a[3] = vec3[3](a0, a1, a2);
    float m[9];
    for (int row = 0; row < 3; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        float linear = a[row].x * bpRestMomentInverse0[col] + a[row].y * bpRestMomentInverse1[col] +
          a[row].z * bpRestMomentInverse2[col];
        m[3 * row + col] = bpLinearBlend * linear + (1.0 - bpLinearBlend) * r[row][col];
      }
    }
    fit.w = m[0];
    linear0 = vec4(m[1], m[2], m[3], m[4]);
    linear1 = vec4(m[5], m[6], m[7], m[8]);
  }
}

// Particle i at p moved towards its goal under the element's fit.
vec3 bpMatchParticle(int i, vec3 p, vec4 fit, vec4 orientation, vec4 linear0, vec4 linear1)
{
  if (bpPinned(i))
  {
    return p;
  }
  vec3 c = fit.xyz;
  vec3 r0, r1, r2;
  if (bpLinearMatching)
  {
    r0 = vec3(fit.w, linear0.x, linear0.y);
    r1 = vec3(linear0.z, linear0.w, linear1.x);
    r2 = vec3(linear1.y, linear1.z, linear1.w);
  }
  else
  {
    bpQuaternionRows(orientation, r0, r1, r2);
  }
  vec3 q = bpElementSize * texelFetch(bpRest, ivec2(i, 0), 0).xyz;
  vec3 goal = c + bpRowsTimes(r0, r1, r2, q);
  return p + bpShapeStiffness * (goal - p);
}

void bpMatchPass(ivec2 texel, int e, int i, inout vec4 fit, inout vec4 orientation,
  inout vec4 linear0, inout vec4 linear1)
{
  orientation = texelFetch(bpOrientations, texel, 0);
  bpMatchElement(e, orientation, fit, linear0, linear1);
}

// bpOrientations holds the fitted rotations here.
void bpMatchApplyPass(ivec2 texel, int e, int i, inout vec4 position, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  ivec2 at = bpElementTexel(e);
  position = vec4(bpMatchParticle(i, bpPositionOf(e, i), texelFetch(bpMatchCenters, at, 0),
                    texelFetch(bpOrientations, at, 0), texelFetch(bpMatchLinear0, at, 0),
                    texelFetch(bpMatchLinear1, at, 0)),
    0.0);
}
