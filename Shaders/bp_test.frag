// Step 5, per element: the reposition test (Engine::stepElement): flag the
// element when its centre (or any particle) left the field or a position is
// not finite, and take the step off its lifetime.
uniform sampler2D bpElementState; // after the reset pass
uniform sampler2D bpPositions;    // after restoration
uniform bool bpAnyParticle;
uniform float bpStep;
uniform bool bpSettleOnly; // after initialisation: clear the placed-now mark, test nothing

out vec4 outState; // (lifetime, generation, flag, non-finite)

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e = texel.y * bpElementGrid.x + texel.x;
  if (e >= bpElements)
  {
    outState = vec4(0.0);
    return;
  }
  vec4 state = texelFetch(bpElementState, texel, 0);
  if (bpSettleOnly)
  {
    outState = vec4(state.x, state.y, 0.0, 0.0);
    return;
  }
  vec3 c = vec3(0.0);
  bool finite = true, anyOutside = false;
  for (int i = 0; i < bpParticles; ++i)
  {
    vec3 q = texelFetch(bpPositions, bpParticleTexel(e, i), 0).xyz;
    finite = finite && bpFinite(q);
    c += q;
    anyOutside = anyOutside || !bpContains(q);
  }
  bool leave = !finite || (bpAnyParticle ? anyOutside : !bpContains(c / float(bpParticles)));
  // A super set's element stays (finalize keeps its last good positions):
  // resetting it alone would tear the structure.
  leave = leave && !bpLinked;
  outState = vec4(state.x - bpStep, state.y, leave ? 1.0 : 0.0, finite ? 0.0 : 1.0);
}
