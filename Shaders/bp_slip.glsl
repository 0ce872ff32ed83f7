// Heavy particles (Core/Engine/Inertia.h; engine specification 2.2), per particle:
// the slip pass, after the reset and before advection, steps each
// particle's slip velocity and writes the displacement it adds to the
// tracer's (bp_advect.glsl reads it); the share pass, after the test, gives
// every particle of a restored element the element's mean slip (shareSlip),
// and 0 to an element whose positions turned non-finite.
uniform sampler2D bpSlips;     // per particle: the slip (xyz)
uniform sampler2D bpSlipsNext; // the share pass: the slip pass's
uniform vec3 bpSlipWeights;    // the second slice's weight at the step's start (x)
uniform float bpSlipTau;       // InertiaStep: tau, E, tau (1 - E), 1 - beta, g
uniform float bpSlipDecay;
uniform float bpSlipMemory;
uniform float bpSlipBuoyancy;
uniform vec3 bpSlipGravity;
uniform float bpTimeRate;      // 1 / (t1 - t0) of the field's slices; 0 when steady
uniform bool bpShareSlip;      // the element is restored (springs, shape matching or links)

// VectorField::sampleWithDerivatives: u, d[a][c] = du_c/dx_a and du/dt at p.
void bpSampleWithDerivatives(vec3 p, float weight, out vec3 u, out vec3 d[3], out vec3 dudt)
{
  bpBlendedGradient(p, weight, d);
  vec3 first = bpSampleSlice(bpField0, p);
  if (!bpUnsteady)
  {
    u = first;
    dudt = vec3(0.0);
    return;
  }
  vec3 second = bpSampleSlice(bpField1, p);
  u = first + weight * (second - first);
  dudt = (second - first) * bpTimeRate;
}

// slipStep: the new slip and the displacement it adds, from the slip `s`.
void bpSlipStep(vec3 u, vec3 d[3], vec3 dudt, inout vec3 s, out vec3 move)
{
  vec3 terminal;
  for (int c = 0; c < 3; ++c)
  {
    float material = dudt[c] + (u.x * d[0][c] + u.y * d[1][c] + u.z * d[2][c]);
    float turning = s.x * d[0][c] + s.y * d[1][c] + s.z * d[2][c];
    terminal[c] = bpSlipTau * (bpSlipBuoyancy * (bpSlipGravity[c] - material) - turning);
  }
  vec3 off = s - terminal;
  move = bpStep * terminal + bpSlipMemory * off;
  s = terminal + bpSlipDecay * off;
}

// Particle i of an element whose state is `element` (z: placed in this step),
// at `p` before advection with slip `s`: its new slip and displacement.
void bpSlipParticle(int i, vec4 element, vec3 p, inout vec3 s, out vec3 move)
{
  move = vec3(0.0);
  if (element.z > 0.5)
  {
    s = vec3(0.0); // placed anew: released with the flow's velocity
  }
  if (bpPinned(i))
  {
    return;
  }
  vec3 u, d[3], dudt;
  bpSampleWithDerivatives(p, bpSlipWeights.x, u, d, dudt);
  bpSlipStep(u, d, dudt, s, move);
}

void bpSlipPass(ivec2 texel, int e, int i, inout vec4 slip, inout vec4 move,
  inout vec4 unused2, inout vec4 unused3)
{
  ivec2 at = bpElementTexel(e);
  vec4 element = texelFetch(bpElementState, at, 0);
  // Where the particle starts the step: placed anew (as bp_advect.glsl
  // places it) or where the last step left it.
  vec3 before = element.z > 0.5
    ? bpPlace(texelFetch(bpCenters, at, 0).xyz, texelFetch(bpOrientations, at, 0),
        texelFetch(bpRest, ivec2(i, 0), 0).xyz)
    : texelFetch(bpState, texel, 0).xyz;
  vec3 s = texelFetch(bpSlips, texel, 0).xyz, m;
  bpSlipParticle(i, element, before, s, m);
  slip = vec4(s, 0.0);
  move = vec4(m, 0.0);
}

// shareSlip, then a non-finite element's slips 0: particle i's slip after
// the step, reading its element's slips through `slipOf`.
void bpSlipSharePass(ivec2 texel, int e, int i, inout vec4 slip, inout vec4 unused1,
  inout vec4 unused2, inout vec4 unused3)
{
  vec4 element = texelFetch(bpElementState, bpElementTexel(e), 0);
  vec3 s = texelFetch(bpSlipsNext, texel, 0).xyz;
  if (bpShareSlip && bpParticles > 1)
  {
    vec3 mean = vec3(0.0);
    for (int k = 0; k < bpParticles; ++k)
    {
      mean += texelFetch(bpSlipsNext, bpParticleTexel(e, k), 0).xyz;
    }
    s = mean / float(bpParticles);
  }
  slip = vec4(element.w > 0.5 ? vec3(0.0) : s, 0.0);
}
