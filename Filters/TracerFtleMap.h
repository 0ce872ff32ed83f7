// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerFtleMap.h
 * @brief The tracer's second output: the FTLE map of a lattice release.
 *
 * With Release Pattern = Lattice, element e is released at lattice point e
 * (Core/Release/ReleaseLattice.h) generation after generation, so its ElementFTLE
 * and ElementStretch, put back at the point it was released from, make an
 * image over the emitter box: the classic FTLE map of its release positions,
 * for the elements' ages at the time shown (with spring-free elements small
 * against the flow's scales, the finite-difference FTLE of neighbouring
 * tracers). ParaView's contouring and volume rendering apply to it.
 */
#ifndef BoundParticles_TracerFtleMap_h
#define BoundParticles_TracerFtleMap_h

#include <array>

class vtkImageData;
class vtkInformation;
class vtkMultiProcessController;

namespace bp
{
class Engine;
}

namespace bpvtk
{
struct FieldProbe;
struct TracerConfig;

/// Whether `config` releases on a lattice, so that the FTLE map is not
/// empty (Release Pattern = Lattice, no seed points, no Linking).
bool mapsLattice(const TracerConfig& config);

/**
 * Sets the FTLE map's whole extent, origin and spacing in `info` (its
 * port's, in RequestInformation) to the lattice `config` releases on over
 * the probed field, so a consumer asks for the points the map will have
 * (Slice, Contour, a view). Empty where the release is not a lattice, or the
 * field could not be probed or refuses the settings (the update says why).
 */
void announceFtleMap(vtkInformation* info, const TracerConfig& config, const FieldProbe& probe);

/**
 * Fills `image` with the FTLE map of `engine`'s elements: dimensions the
 * lattice's counts, origin its first point plus `offset` (the world position
 * of the grid-local origin), spacing the lattice's (1 along a flat axis);
 * point arrays "FTLE", "Stretch" (largest, smallest), "Age" and
 * vtkValidPointMask (1 where element e is released, shown and old enough
 * for an FTLE, Parameters::ftleMinimumAge; 0, with FTLE 0 and Stretch 1,
 * where it is not yet, is younger, or its point lies outside the flow).
 * Empty unless the
 * engine releases on a lattice of as many points as elements.
 *
 * With a `controller` (a distributed run, whose processes each hold some of
 * the elements) every process gives its own and process 0 gets the whole
 * image while the others get an empty one: collective.
 */
void fillFtleMap(vtkImageData* image, const bp::Engine& engine, const std::array<double, 3>& offset,
  vtkMultiProcessController* controller);

} // namespace bpvtk

#endif
