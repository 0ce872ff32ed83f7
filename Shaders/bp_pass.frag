// The fragment main of a pass (bp_pass.glsl): a fragment per texel of the
// pass's domain, drawn over bp_fullscreen.vert, its values into the colour
// attachments. The fragment path: every OpenGL 3.3 context.
layout(location = 0) out vec4 bpTarget0;
#if BP_TARGETS > 1
layout(location = 1) out vec4 bpTarget1;
#endif
#if BP_TARGETS > 2
layout(location = 2) out vec4 bpTarget2;
#endif
#if BP_TARGETS > 3
layout(location = 3) out vec4 bpTarget3;
#endif

void main()
{
  vec4 o0, o1, o2, o3;
  bpRunPass(ivec2(gl_FragCoord.xy), o0, o1, o2, o3);
  bpTarget0 = o0;
#if BP_TARGETS > 1
  bpTarget1 = o1;
#endif
#if BP_TARGETS > 2
  bpTarget2 = o2;
#endif
#if BP_TARGETS > 3
  bpTarget3 = o3;
#endif
}
