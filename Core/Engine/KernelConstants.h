// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file KernelConstants.h
 * @brief The one list of the numbers the C++ code and the GPU engine's
 * kernels (Shaders/) share.
 *
 * BP_KERNEL_CONSTANTS(X) has one row X(NAME, Type, value, Use) per number:
 * `value` is the C++ constant, defined beside its meaning (or here, where it
 * has no other home); Gpu/ShaderSource.cpp writes each row whose Use is not
 * HostOnly into every kernel as `#define BP_<NAME> <value>`, as a GLSL
 * `Type` (Int, Uint with its `u`, Float in the fewest digits that read back
 * as the same float), so a kernel names the number and cannot drift from
 * C++. Use says who names it:
 *  - Kernels: a kernel names BP_<NAME>;
 *  - EnumValue: a value of an enum the kernels compare with, defined so the
 *    enum is whole (a kernel names its other values, and reaches this one in
 *    an else branch);
 *  - HostOnly: C++ only, for two C++ files that must agree (not written).
 *
 * Testing/Core/TestKernelConstants.cpp reads every file in Shaders/ and fails
 * on a literal copy of a row's value, on a Kernels row no kernel names, and
 * on a work-group size or an enum comparison written as a bare digit.
 */
#ifndef BoundParticles_KernelConstants_h
#define BoundParticles_KernelConstants_h

#include "CounterHash.h"
#include "EngineParameters.h"
#include "MaskWalls.h"
#include "ParticleLayout.h"
#include "Pose.h"
#include "Quaternion.h"
#include "ReleaseWeights.h"
#include "ShapeMatching.h"
#include "Walls.h"

namespace bp
{

/// Seed points a row of the seed points' list texture (bpSeedPoints,
/// GpuSystem): a seed point's texel is (i % SeedPointsPerRow, i / SeedPointsPerRow).
constexpr int SeedPointsPerRow = 256;

/// Outlet triangles a row of the Outlets' texture (bpOutlets, GpuSystem), 3
/// texels each: corner c of triangle k is texel (3 (k % OutletsPerRow) + c,
/// k / OutletsPerRow). The Walls' texture (bpWalls) is laid out the same.
constexpr int OutletsPerRow = 256;

/// How far outside an Outlet or Wall triangle's edges, in barycentric units,
/// the kernels (bp_test.glsl: bpMeetOutlet, bp_common.glsl: bpMeetWall)
/// still count a hit: in float,
/// as SurfaceCrossings' 1e-9 in double, a step through an edge that two
/// triangles share must not fall between them by a rounding.
constexpr float OutletEdgeSlack = 1e-6f;

/// The compute path's pass work group (bp_pass.comp): PassGroupSize x
/// PassGroupSize invocations, one per texel of the pass's domain
/// (GpuPass::dispatch).
constexpr int PassGroupSize = 8;

/// Who names a row of BP_KERNEL_CONSTANTS (this file's comment says more).
enum class KernelConstantUse
{
  Kernels,
  EnumValue,
  HostOnly
};

} // namespace bp

// clang-format off
#define BP_KERNEL_CONSTANTS(X)                                                                    \
  X(RELEASE_TRIES, Int, ::bp::ReleaseTries, Kernels)                                              \
  X(MATCH_ITERATIONS, Int, ::bp::MatchIterations, Kernels)                                        \
  X(POSE_ITERATIONS, Int, ::bp::PoseIterations, Kernels)                                          \
  X(ROTATION_DAMPING, Float, ::bp::RotationDamping, Kernels)                                      \
  X(MAX_NEWTON_STEP, Float, ::bp::MaxNewtonStep, Kernels)                                         \
  X(MIN_VORTICITY_STEP, Float, ::bp::MinVorticityStep, Kernels)                                   \
  X(MAX_SPIN_VORTICITY_RATIO, Float, ::bp::MaxSpinVorticityRatio, Kernels)                        \
  X(HASH_MULTIPLIER, Uint, ::bp::HashMultiplier, Kernels)                                         \
  X(HASH_INCREMENT, Uint, ::bp::HashIncrement, Kernels)                                           \
  X(HASH_UNIT, Float, ::bp::HashUnit, Kernels)                                                    \
  X(ORIENTATION_DRAW, Uint, ::bp::OrientationDraw, Kernels)                                       \
  X(LIFETIME_DRAW, Uint, ::bp::LifetimeDraw, Kernels)                                             \
  X(FURTHER_CANDIDATE_DRAW, Uint, ::bp::FurtherCandidateDraw, Kernels)                            \
  X(FIRST_WEIGHT_DRAW, Uint, ::bp::FirstWeightDraw, Kernels)                                      \
  X(SEED_ROW, Uint, ::bp::SeedPointsPerRow, Kernels)                                              \
  X(OUTLET_ROW, Int, ::bp::OutletsPerRow, Kernels)                                                \
  X(OUTLET_EDGE_SLACK, Float, ::bp::OutletEdgeSlack, Kernels)                                     \
  X(ANTIPARALLEL_TOLERANCE, Float, ::bp::AntiparallelTolerance, Kernels)                          \
  X(PI, Float, ::bp::Pi, Kernels)                                                                 \
  X(PASS_GROUP_SIZE, Int, ::bp::PassGroupSize, Kernels)                                           \
  X(LIST_WIDTH, Int, ::bp::ListTextureWidth, HostOnly)                                            \
  X(ORIENTATION_FIXED, Int, int(::bp::Orientation::Fixed), Kernels)                               \
  X(ORIENTATION_RANDOM, Int, int(::bp::Orientation::Random), Kernels)                             \
  X(ORIENTATION_ALONG_FLOW, Int, int(::bp::Orientation::AlongFlow), EnumValue)                    \
  X(INTEGRATOR_EULER, Int, int(::bp::Integrator::Euler), Kernels)                                 \
  X(INTEGRATOR_RK2, Int, int(::bp::Integrator::RK2), Kernels)                                     \
  X(INTEGRATOR_RK4, Int, int(::bp::Integrator::RK4), EnumValue)                                  \
  X(BOUNDARY_RELEASE_AGAIN, Int, int(::bp::Boundary::ReleaseAgain), Kernels)                      \
  X(BOUNDARY_TERMINATE, Int, int(::bp::Boundary::Terminate), Kernels)                            \
  X(BOUNDARY_STICK, Int, int(::bp::Boundary::Stick), Kernels)                                    \
  X(BOUNDARY_SLIP, Int, int(::bp::Boundary::Slip), Kernels)                                      \
  X(BOUNDARY_BOUNCE, Int, int(::bp::Boundary::Bounce), Kernels)                                \
  X(WALL_MASKED_CELL, Int, int(::bp::WallMaskedCell), Kernels)                                     \
  X(MASK_WALL_CROSSINGS, Int, ::bp::MaxMaskWallCrossings, Kernels)                                 \
  X(MASK_WALL_RULES, Int, ::bp::MaxMaskWallRules, Kernels)
// clang-format on

#endif
