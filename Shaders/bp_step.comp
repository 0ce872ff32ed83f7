// The compute path's fused step: a whole step of every element in one
// dispatch, for a system without links whose elements fit a workgroup
// (FusedStep::of in GpuPasses.cpp). The same kernels as the passes
// (bp_reset.glsl to bp_pose.glsl) in the same order, each element's
// particles held in shared memory between them: the particle state is read once and written
// once, the per-element state likewise, and an element's K restoration
// iterations run with barriers between them instead of passes.
//
// A workgroup holds BP_GROUP_ELEMENTS consecutive elements of BP_N
// particles. In the particle phases thread t works on particle t / G of
// element t % G (G = BP_GROUP_ELEMENTS), so neighbouring threads read
// neighbouring texels and run the same springs; in the per-element phases
// (reset, shape matching's fit, test, pose) thread t < G works on element t,
// so those phases run on whole SIMD groups while the other threads wait at
// the barrier (a GPU runs other workgroups meanwhile). Gpu/GpuPasses.cpp
// defines BP_N, BP_GROUP_ELEMENTS, BP_GROUP_THREADS (their product) and
// BP_RESTORATION (one of BP_FUSED_NONE, _JACOBI, _GAUSS_SEIDEL and
// _SHAPE_MATCHING, which it defines from GpuPasses.h's FusedRestore), the
// trace's specialisation (KernelSpecialisation: BP_INTEGRATOR, and
// BP_TRACK_POSES and BP_INERTIAL where poses are fitted and particles are
// heavy), and declares the images it writes: the particle state's next texture
// (bpParticlesOut) and each per-element texture's (bpElementStateOut,
// bpCentersOut, bpOrientationsOut, bpPosesOut, bpSpinsOut: GpuState's one
// list). Workgroups run along x, then y, as many as the system needs.
layout(local_size_x = BP_GROUP_THREADS) in;

uniform int bpIterations;  // K
uniform int bpColourCount; // Gauss-Seidel: colours of springs

// The positions of the phase at hand (particle i of element e0 + k at
// i * G + k), then the elements' per-element values.
shared vec3 bpLocalPositions[BP_GROUP_THREADS];
shared vec4 bpLocalState[BP_GROUP_ELEMENTS];
shared vec4 bpLocalCenter[BP_GROUP_ELEMENTS];
shared vec4 bpLocalOrientation[BP_GROUP_ELEMENTS];
shared vec4 bpLocalFit[BP_GROUP_ELEMENTS]; // shape matching's fit, then the test's move
shared vec4 bpLocalLinear0[BP_GROUP_ELEMENTS];
shared vec4 bpLocalLinear1[BP_GROUP_ELEMENTS];
#ifdef BP_INERTIAL
// Heavy particles (bp_slip.glsl): each particle's new slip, for its
// element's mean after the test.
shared vec3 bpLocalSlips[BP_GROUP_THREADS];
#endif

// Every thread of the workgroup here, and what they wrote to shared memory
// visible to all (barrier() alone orders execution; OpenGL's GLSL leaves its
// effect on shared memory to memoryBarrierShared()).
#define bpSync()             \
  memoryBarrierShared();     \
  barrier()

int bpGroupFirstElement()
{
  int group = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
  return group * BP_GROUP_ELEMENTS;
}

vec3 bpPositionOf(int e, int i)
{
  return bpLocalPositions[i * BP_GROUP_ELEMENTS + e - bpGroupFirstElement()];
}

void main()
{
  int thread = int(gl_LocalInvocationID.x);
  int first = bpGroupFirstElement();
  // This thread's particle ...
  int i = thread / BP_GROUP_ELEMENTS, local = thread - i * BP_GROUP_ELEMENTS;
  int e = first + local;
  bool live = e < bpElements;
  ivec2 texel = bpParticleTexel(e, i);
  // ... and, for thread < G, its element.
  int own = first + thread;
  bool lead = thread < BP_GROUP_ELEMENTS && own < bpElements;
  ivec2 at = bpElementTexel(own);

  // 1. Reset.
  vec4 pose = vec4(0.0);
  if (lead)
  {
    vec4 state = texelFetch(bpElementState, at, 0);
    vec4 center = texelFetch(bpCenters, at, 0);
    vec4 orientation = texelFetch(bpOrientations, at, 0);
    pose = texelFetch(bpPoses, at, 0);
    bpResetElement(own, state, center, orientation, pose);
    bpLocalState[thread] = state;
    bpLocalCenter[thread] = center;
    bpLocalOrientation[thread] = orientation;
    imageStore(bpCentersOut, at, center);
  }
  bpSync();

  // 2. Advect.
  vec3 before = vec3(0.0), advected = vec3(0.0);
#ifdef BP_INERTIAL
  vec3 slip = vec3(0.0);
#endif
  if (live)
  {
    bpAdvectParticle(i, bpLocalState[local], bpLocalCenter[local], bpLocalOrientation[local],
      texelFetch(bpState, texel, 0).xyz, before, advected);
#ifdef BP_INERTIAL
    // The slip's step from where the particle starts, and its displacement
    // added to the tracer's (the slip and advect passes).
    vec3 move;
    slip = texelFetch(bpSlips, texel, 0).xyz;
    bpSlipParticle(i, bpLocalState[local], before, slip, move);
    advected += move;
#endif
    // The walls (Boundary Stick, Slip, Bounce): the advect pass's, and the
    // slip share pass's rule on the velocity.
    if (bpMeetsWalls(i, before))
    {
      int hits = bpWallParticle(before, advected, bpWeights.z);
#ifdef BP_INERTIAL
      slip = bpWallSlip(hits, advected, slip, bpEndWeight);
#endif
      // The Surfaces' Walls (Stick, Slip, Bounce), and their rule on the velocity.
      int met = bpWallsParticles() ? bpWallOnSurfaces(before, advected) : 0;
#ifdef BP_INERTIAL
      slip = bpWallSlipOnSurfaces(met, advected, slip, bpEndWeight);
#endif
    }
  }
  bpLocalPositions[thread] = advected;
  vec3 p = advected;
  bpSync();

  // 3. Restore: K iterations, each phase's positions shared once every
  // thread has read the last ones.
  for (int k = 0; k < bpIterations; ++k)
  {
#if BP_RESTORATION == BP_FUSED_JACOBI
    if (live)
    {
      p = bpJacobiParticle(e, i, p);
    }
    bpSync();
    bpLocalPositions[thread] = p;
    bpSync();
#elif BP_RESTORATION == BP_FUSED_GAUSS_SEIDEL
    for (int colour = 0; colour < bpColourCount; ++colour)
    {
      if (live)
      {
        p = bpGaussSeidelParticle(e, i, p, colour);
      }
      bpSync();
      bpLocalPositions[thread] = p;
      bpSync();
    }
#elif BP_RESTORATION == BP_FUSED_SHAPE_MATCHING
    if (lead)
    {
      vec4 orientation = bpLocalOrientation[thread], fit, linear0, linear1;
      bpMatchElement(own, orientation, fit, linear0, linear1);
      bpLocalOrientation[thread] = orientation;
      bpLocalFit[thread] = fit;
      bpLocalLinear0[thread] = linear0;
      bpLocalLinear1[thread] = linear1;
    }
    bpSync();
    if (live)
    {
      p = bpMatchParticle(i, p, bpLocalFit[local], bpLocalOrientation[local],
        bpLocalLinear0[local], bpLocalLinear1[local]);
    }
    bpSync();
    bpLocalPositions[thread] = p;
    bpSync();
#endif
  }

  // The walls after restoration (the wall pass), before the test reads them.
  if (bpWalled())
  {
    if (live)
    {
      p = bpWallRestored(p, advected, bpEndWeight);
      p = bpWallsParticles() ? bpWallRestoredOnSurfaces(p, advected) : p;
    }
    bpSync();
    bpLocalPositions[thread] = p;
    bpSync();
  }

  // The Outlets and the Walls that end elements (bp_test.glsl): each
  // element's centre before the step, its
  // particles' positions before it summed by its lead thread, then the
  // restored positions shared again for the test.
  vec3 from = vec3(0.0);
  if (bpTestsPassages())
  {
    bpLocalPositions[thread] = before;
    bpSync();
    for (int k = 0; lead && k < bpParticles; ++k)
    {
      from += bpPositionOf(own, k);
    }
    from /= float(bpParticles);
    bpSync();
    bpLocalPositions[thread] = p;
    bpSync();
  }

  // 4. Test, on the restored positions.
  if (lead)
  {
    vec4 tested, shift;
    bpTestElement(own, bpLocalState[thread], bpLocalCenter[thread], from, tested, shift);
    bpLocalState[thread] = tested;
    bpLocalFit[thread] = shift;
    imageStore(bpElementStateOut, at, tested);
    imageStore(bpOrientationsOut, at, bpLocalOrientation[thread]);
  }
  bpSync();

  // 5. Finalize.
  vec4 after = vec4(0.0);
  if (live)
  {
    after = bpFinalParticle(p, advected, before, bpLocalState[local], bpLocalFit[local]);
    imageStore(bpParticlesOut, texel, after);
  }
#ifdef BP_INERTIAL
  // A restored element's mean slip, 0 where its positions turned non-finite
  // (the share pass).
  bpLocalSlips[thread] = slip;
  bpSync();
  if (live)
  {
    if (bpShareSlip && bpParticles > 1)
    {
      vec3 mean = vec3(0.0);
      for (int k = 0; k < BP_N; ++k)
      {
        mean += bpLocalSlips[k * BP_GROUP_ELEMENTS + local];
      }
      slip = mean / float(bpParticles);
    }
    imageStore(bpSlipsOut, texel, vec4(bpLocalState[local].w > 0.5 ? vec3(0.0) : slip, 0.0));
  }
#endif

  // 6. Poses and spins, from the positions after the step.
#ifdef BP_TRACK_POSES
  bpSync();
  bpLocalPositions[thread] = after.xyz;
  bpSync();
  if (lead)
  {
    vec4 spin;
    bpPoseElement(own, bpLocalState[thread], pose, spin);
    imageStore(bpSpinsOut, at, spin);
  }
#endif
  if (lead)
  {
    imageStore(bpPosesOut, at, pose);
  }
}
