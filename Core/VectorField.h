// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VectorField.h
 * @brief A vector field on a uniform grid, sampled trilinearly in space and
 * linearly in time between two time steps (thesis §3.4).
 *
 * Positions outside the grid sample the nearest boundary value, as the thesis'
 * clamped 3D textures do; the engine decides separately when an element has
 * left the field. An axis with a single grid point is a plane: sampling ignores
 * it and so does the bounds test, so 2D data sets need no special case.
 */
#ifndef BoundParticles_VectorField_h
#define BoundParticles_VectorField_h

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

/// Point positions x_i = origin + i * spacing, x fastest (VTK's point order).
struct GridGeometry
{
  std::array<int, 3> dims = { 0, 0, 0 };
  std::array<double, 3> origin = { 0, 0, 0 };
  std::array<double, 3> spacing = { 1, 1, 1 };

  std::size_t pointCount() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  /// Empty when the grid can carry a flow, otherwise why not.
  std::string validate() const;
  std::array<double, 6> bounds() const;
  double diagonal() const;
  /// Mean spacing over the axes with more than one point.
  double cellLength() const;
};

/// One time step: 3 floats per grid point.
struct FieldSlice
{
  double time = 0.0;
  std::shared_ptr<const std::vector<float>> velocity;
};

class VectorField
{
public:
  /// A steady field: one slice.
  VectorField(const GridGeometry& grid, FieldSlice slice);
  /// An unsteady field between two slices with first.time < second.time.
  VectorField(const GridGeometry& grid, FieldSlice first, FieldSlice second);

  const GridGeometry& grid() const { return this->Grid; }
  bool isSteady() const { return !this->Second.velocity; }

  /// Velocity at p and time t.
  void sample(const float p[3], double t, float v[3]) const;

  /// |curl v| at p and time t, by central differences one cell apart.
  float vorticityMagnitude(const float p[3], double t) const;

  /// Whether p lies in the grid's bounds (axes of one point are ignored).
  bool contains(const float p[3]) const;

  /// Largest speed over the grid points of the first slice.
  double maxSpeed() const;

  /// Empty when every value of every slice is finite and the slices match the grid.
  std::string validate() const;

  const FieldSlice& firstSlice() const { return this->First; }
  const FieldSlice& secondSlice() const { return this->Second; }

  /// Weight of the second slice at time t (0 for a steady field).
  float timeWeight(double t) const;

  /// The float constants sampling and the bounds test use, so that another
  /// implementation (the GPU engine) computes with the very same numbers.
  struct SamplingConstants
  {
    float origin[3], inverseSpacing[3], maxIndex[3], lower[3], upper[3];
    bool degenerate[3];
  };
  SamplingConstants samplingConstants() const;

private:
  void sampleSlice(const float* data, const float p[3], float v[3]) const;

  GridGeometry Grid;
  FieldSlice First;
  FieldSlice Second;
  // Precomputed for the hot loop.
  float Origin[3];
  float InverseSpacing[3];
  float MaxIndex[3];
  float Lower[3];
  float Upper[3];
  bool Degenerate[3];
  std::size_t Stride[3];
};

} // namespace bp

#endif
