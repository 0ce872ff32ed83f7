// Step 3 with shape matching, per element (Engine::matchShape): the centre of
// the particles and their moment (bpMomentOf), and the rotation of the best
// rigid fit to the rest shape; in the linear mode also the goal matrix
// M = beta * A Aqq^-1 + (1 - beta) * R, packed row by row into outCenter.w,
// outLinear0 and outLinear1.
uniform sampler2D bpPositions;
uniform sampler2D bpRest;
uniform sampler2D bpOrientations;
uniform bool bpLinearMatching;
uniform float bpLinearBlend;        // beta
uniform vec3 bpRestMomentInverse0; // rows of Aqq^-1 (restMomentInverse)
uniform vec3 bpRestMomentInverse1;
uniform vec3 bpRestMomentInverse2;

layout(location = 0) out vec4 outCenter;
layout(location = 1) out vec4 outOrientation;
layout(location = 2) out vec4 outLinear0;
layout(location = 3) out vec4 outLinear1;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e;
  outLinear0 = vec4(0.0);
  outLinear1 = vec4(0.0);
  if (!bpElementOf(texel, e))
  {
    outCenter = vec4(0.0);
    outOrientation = vec4(0.0);
    return;
  }
  vec3 c, a0, a1, a2;
  bpMomentOf(bpPositions, bpRest, e, c, a0, a1, a2);
  outCenter = vec4(c, 0.0);
  outOrientation = bpFitRotation(a0, a1, a2, texelFetch(bpOrientations, texel, 0),
    BP_MATCH_ITERATIONS);
  if (bpLinearMatching)
  {
    vec3 r[3];
    bpQuaternionRows(outOrientation, r[0], r[1], r[2]);
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
    outCenter.w = m[0];
    outLinear0 = vec4(m[1], m[2], m[3], m[4]);
    outLinear1 = vec4(m[5], m[6], m[7], m[8]);
  }
}
