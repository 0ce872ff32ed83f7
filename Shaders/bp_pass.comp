// The compute main of a pass (bp_pass.glsl): an invocation per texel of the
// pass's domain, in tiles of BP_PASS_GROUP_SIZE x BP_PASS_GROUP_SIZE (as
// GpuPass::dispatch counts them), its values stored into the target
// images (GpuPass::run binds them to image units 0, 1, ...). The compute
// path: OpenGL 4.3 and later.
layout(local_size_x = BP_PASS_GROUP_SIZE, local_size_y = BP_PASS_GROUP_SIZE) in;
layout(rgba32f, binding = 0) uniform writeonly image2D bpTarget0;
#if BP_TARGETS > 1
layout(rgba32f, binding = 1) uniform writeonly image2D bpTarget1;
#endif
#if BP_TARGETS > 2
layout(rgba32f, binding = 2) uniform writeonly image2D bpTarget2;
#endif
#if BP_TARGETS > 3
layout(rgba32f, binding = 3) uniform writeonly image2D bpTarget3;
#endif
uniform ivec2 bpDomainSize; // texels
uniform int bpTargetCount;  // targets bound: a pass may leave its last ones off

void main()
{
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= bpDomainSize.x || texel.y >= bpDomainSize.y)
  {
    return;
  }
  vec4 o0, o1, o2, o3;
  bpRunPass(texel, o0, o1, o2, o3);
  imageStore(bpTarget0, texel, o0);
#if BP_TARGETS > 1
  if (bpTargetCount > 1)
  {
    imageStore(bpTarget1, texel, o1);
  }
#endif
#if BP_TARGETS > 2
  if (bpTargetCount > 2)
  {
    imageStore(bpTarget2, texel, o2);
  }
#endif
#if BP_TARGETS > 3
  if (bpTargetCount > 3)
  {
    imageStore(bpTarget3, texel, o3);
  }
#endif
}
