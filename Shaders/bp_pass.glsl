// A kernel run as a pass of its own, one invocation per texel of its domain:
// what the fragment main (bp_pass.frag) and the compute main (bp_pass.comp)
// share. Gpu/GpuPasses.cpp names the kernel's pass function (BP_PASS, as
// bpAdvectPass in bp_advect.glsl), its domain (BP_PER_ELEMENT, else per
// particle) and its number of targets (BP_TARGETS, at most 4).

vec3 bpPositionOf(int e, int i)
{
  return texelFetch(bpPositions, bpParticleTexel(e, i), 0).xyz;
}

// The pass at `texel`: its targets' values, 0 outside the system.
void bpRunPass(ivec2 texel, out vec4 o0, out vec4 o1, out vec4 o2, out vec4 o3)
{
  o0 = vec4(0.0);
  o1 = vec4(0.0);
  o2 = vec4(0.0);
  o3 = vec4(0.0);
  int e, i = 0;
#ifdef BP_PER_ELEMENT
  bool inside = bpElementOf(texel, e);
#else
  bool inside = bpParticleOf(texel, e, i);
#endif
  if (inside)
  {
    BP_PASS(texel, e, i, o0, o1, o2, o3);
  }
}
