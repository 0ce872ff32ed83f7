// Step 5, per element: the reposition test (Engine::settle): flag the
// element when its centre (or any particle) left the field or entered a cell
// outside the flow's domain, when in its first step its centre moved slower
// than the release speed, or when a position is not finite; and take the
// step off its lifetime.
uniform sampler2D bpElementState; // after the reset pass
uniform sampler2D bpPositions;    // after restoration
uniform sampler2D bpCenters;      // release centres
uniform bool bpAnyParticle;
uniform float bpStep;
uniform float bpEndWeight;       // the second time step's weight after the step
uniform float bpReleaseMinSpeed; // 0: every release stays

// Engine::releasedStagnant.
bool bpReleasedStagnant(int e, vec4 state, vec3 c)
{
  if (!(bpReleaseMinSpeed > 0.0) || bpLinked)
  {
    return false;
  }
  vec3 d = c - texelFetch(bpCenters, bpElementTexel(e), 0).xyz;
  float reach = bpReleaseMinSpeed * bpStep;
  return dot(d, d) < reach * reach && bpLifetimeOf(e, state.y) - state.x < 0.5 * bpStep;
}
uniform bool bpSettleOnly; // after initialisation: clear the placed-now mark, test nothing
// Anchor = Centre: the element is tested where it is moved back to, its
// release centre, and the move is written for the finalize pass.
uniform bool bpAnchored;

layout(location = 0) out vec4 outState; // (lifetime, generation, flag, non-finite)
layout(location = 1) out vec4 outShift; // anchored: the element's move (only then a target)

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e;
  if (!bpElementOf(texel, e))
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
    anyOutside = anyOutside || !bpInDomain(q, bpEndWeight);
  }
  c /= float(bpParticles);
  vec3 at = c;
  if (bpAnchored)
  {
    // Engine::anchor: every particle moved by the release centre minus the
    // mean; the release-speed test below still reads the mean the flow gave.
    at = texelFetch(bpCenters, bpElementTexel(e), 0).xyz;
    vec3 shift = at - c;
    outShift = vec4(shift, 0.0);
    anyOutside = false;
    for (int i = 0; bpAnyParticle && i < bpParticles; ++i)
    {
      vec3 q = texelFetch(bpPositions, bpParticleTexel(e, i), 0).xyz + shift;
      anyOutside = anyOutside || !bpInDomain(q, bpEndWeight);
    }
  }
  bool leave = !finite || (bpAnyParticle ? anyOutside : !bpInDomain(at, bpEndWeight)) ||
    bpReleasedStagnant(e, state, c);
  // A super set's element stays (finalize keeps its last good positions):
  // resetting it alone would tear the structure.
  leave = leave && !bpLinked;
  outState = vec4(state.x - bpStep, state.y, leave ? 1.0 : 0.0, finite ? 0.0 : 1.0);
}
