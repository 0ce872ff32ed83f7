// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EigenRows.h
 * @brief An Eigen 3x3 matrix as the row-major floats the engines keep
 * (rotations, a template's inverse rest moment). Included only by .cpp files
 * of Core/, so no header of the engine pulls in Eigen.
 */
#ifndef BoundParticles_EigenRows_h
#define BoundParticles_EigenRows_h

#include <Eigen/Core>

#include <array>

namespace bp
{

/// The matrix rounded to float, row by row.
inline std::array<float, 9> toRowMajor(const Eigen::Matrix3d& m)
{
  std::array<float, 9> rows;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rows[3 * i + j] = float(m(i, j));
    }
  }
  return rows;
}

} // namespace bp

#endif
