// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuEngineState.h
 * @brief The GPU engine's state as a bp::EngineState (Core/Engine/EngineState.h):
 * read back from its textures, and uploaded into them, so that a state the
 * CPU engine saved resumes on the GPU (GpuEngine::readState, loadState).
 *
 * The record is the CPU engine's (Engine::stateLayout); each array comes
 * from, or goes into, a texture of GpuState: Lifetimes, Generations and the
 * ResetDue flag are ElementTexture::State's x, y and z; ReleaseHidden is
 * Centers.w, InitialCenters its xyz; Orientations, Poses and Spins their
 * rows; Positions and Forces the particle texture's xyz and w; Slips the
 * slips' xyz; a trail slot's TrailPositions its particle texture's xyz and
 * its TrailGenerations its element texture's y (-1: NoTrailPose). What the
 * record does not hold is 0 after an upload: State.w (the non-finite flag,
 * read only inside the step that sets it), a trail slot's forces, lifetimes
 * and flags (its colour only). The texture's padding keeps its texels.
 */
#ifndef BoundParticles_GpuEngineState_h
#define BoundParticles_GpuEngineState_h

#include "EngineState.h"

#include <string>

namespace bp
{
class GpuSystem;

/// The state at the step boundary (with `saved`, save()'s copy: a short step
/// is shown past it) into `out`; empty on success, otherwise why not.
std::string readEngineState(const GpuSystem& system, bool saved, EngineState& out);

/// Replaces every element by the state's (checkEngineState, then the GPU's
/// own limits: bp::gpuStateRefusal), with its trail ring and emitter box;
/// empty on success, otherwise why not (nothing changed then).
std::string loadEngineState(GpuSystem& system, const EngineState& state);

} // namespace bp

#endif
