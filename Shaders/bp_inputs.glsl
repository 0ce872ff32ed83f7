// What several of the GPU engine's kernels read, declared once (a program
// that puts several kernels together, the compute path's fused step, has
// each declaration once). After bp_shared.glsl and the per-element state's
// samplers (bpElementState, bpCenters, bpOrientations, bpPoses, bpSpins),
// which Gpu/GpuState.cpp declares from its one list; before bp_common.glsl.

// Per particle: the state after the last step (position, force), read at
// the particle's own texel.
uniform sampler2D bpState;
// Per particle: the positions the kernel at hand works on (after advection
// or the last restoration pass; after the step for the pose and normals).
uniform sampler2D bpPositions;
// Particle i of element e in those positions: a texel of bpPositions in a
// pass of its own (bp_pass.glsl), the workgroup's shared memory in the
// fused step (bp_step.comp).
vec3 bpPositionOf(int e, int i);

// The template: n x 1 rest positions; n x 2 per particle (spring offset,
// count, 1/degree, pinned), (triangle offset, count, 0, 0).
uniform sampler2D bpRest;
uniform sampler2D bpParticleInfo;

uniform float bpStep;          // float(h)
uniform float bpEndWeight;     // the second time step's weight at t + h
uniform bool bpAnchored;       // Anchor = Centre (bp_test.glsl, bp_finalize.glsl)
uniform bool bpShiftsPeriodic; // a periodic field: finalize applies the test's shifts
uniform bool bpLinearMatching; // linear shape matching (bp_match.glsl)
// Heavy particles (bp_slip.glsl): per particle, the displacement the slip adds
// to the tracer's in this step (bp_advect.glsl adds it in a program compiled
// with BP_INERTIAL).
uniform sampler2D bpSlipMoves;
// Per particle: its position after advection and the walls (.w: what the
// walls did, bp_common.glsl's bpWallParticle), for the finalize pass's force,
// the walls after restoration and the slip share pass.
uniform sampler2D bpAdvected;
// Per particle: its position before the step (placed anew where the reset
// pass placed its element), written by the advect pass: for the finalize
// pass's non-finite elements and the test pass's Outlets (bp_test.glsl).
uniform sampler2D bpBefore;

// Whether particle i is pinned (it never moves).
bool bpPinned(int i)
{
  return texelFetch(bpParticleInfo, ivec2(i, 0), 0).w > 0.5;
}
