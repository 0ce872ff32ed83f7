// Step 5, per particle: the new state. A non-finite element keeps its
// positions from before the step (so nothing non-finite is ever drawn); the
// force is the length of the restoration displacement.
uniform sampler2D bpRestored;
uniform sampler2D bpAdvected;
uniform sampler2D bpBefore;
uniform sampler2D bpElementState; // after the test pass
uniform bool bpAnchored;          // Anchor = Centre: move by the test pass's shift
uniform sampler2D bpShifts;       // per element, from the test pass (anchored only)

out vec4 outState;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e, i;
  if (!bpParticleOf(texel, e, i))
  {
    outState = vec4(0.0);
    return;
  }
  if (texelFetch(bpElementState, bpElementTexel(e), 0).w > 0.5)
  {
    outState = vec4(texelFetch(bpBefore, texel, 0).xyz, 0.0);
    return;
  }
  vec3 q = texelFetch(bpRestored, texel, 0).xyz;
  vec3 d = q - texelFetch(bpAdvected, texel, 0).xyz;
  if (bpAnchored)
  {
    // The force stays the restoration's: it is taken before the move.
    q += texelFetch(bpShifts, bpElementTexel(e), 0).xyz;
  }
  outState = vec4(q, sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
}
