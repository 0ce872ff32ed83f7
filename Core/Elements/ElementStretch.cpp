// SPDX-License-Identifier: BSD-3-Clause
// The best linear fit of an element against its template, its principal
// stretches and the FTLE (ElementStretch.h).
#include "ElementStretch.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace bp
{

namespace
{
/// Directions whose second moment is below this fraction of the largest are
/// not spanned: a flat template's normal has a moment of rounding's size.
constexpr double SpanTolerance = 1e-8;
} // namespace

StretchFit::StretchFit(const std::vector<std::array<float, 3>>& rest, double size)
{
  const std::size_t n = rest.size();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& r : rest)
  {
    mean += Eigen::Vector3d(r[0], r[1], r[2]) * size;
  }
  mean /= double(std::max<std::size_t>(n, 1));
  Eigen::Matrix3d Aqq = Eigen::Matrix3d::Zero();
  this->Centred.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3d q = Eigen::Vector3d(rest[i][0], rest[i][1], rest[i][2]) * size - mean;
    this->Centred[i] = { q[0], q[1], q[2] };
    Aqq += q * q.transpose();
  }
  // The pseudo-inverse over the directions the template spans.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Aqq);
  const Eigen::Vector3d lambda = eig.eigenvalues(); // ascending
  const double largest = lambda[2];
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k)
  {
    if (largest > 0.0 && lambda[k] > SpanTolerance * largest)
    {
      const Eigen::Vector3d v = eig.eigenvectors().col(k);
      B += v * v.transpose() / lambda[k];
      ++this->Span;
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->B[3 * r + c] = B(r, c);
    }
  }
}

std::array<float, 2> StretchFit::stretch(const float* positions) const
{
  const std::size_t n = this->Centred.size();
  if (this->Span == 0)
  {
    return { 1.0f, 1.0f };
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i)
  {
    mean += Eigen::Vector3d(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
  }
  mean /= double(n);
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3d p =
      Eigen::Vector3d(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]) - mean;
    const auto& q = this->Centred[i];
    A += p * Eigen::RowVector3d(q[0], q[1], q[2]);
  }
  const Eigen::Matrix3d B = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(this->B);
  // F = A B maps the span and is 0 off it: F^T F has the squared stretches
  // as its `Span` largest eigenvalues, and zeros for the rest.
  const Eigen::Matrix3d F = A * B;
  if (!F.allFinite())
  {
    return { 1.0f, 1.0f };
  }
  const Eigen::Vector3d s2 =
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(F.transpose() * F, Eigen::EigenvaluesOnly)
      .eigenvalues();
  const double largest = std::sqrt(std::max(s2[2], 0.0));
  const double smallest = std::sqrt(std::max(s2[3 - this->Span], 0.0));
  return { float(largest), float(smallest) };
}

float elementFtle(float largestStretch, double age, double minimumAge)
{
  if (!(age > 0.0) || !(age >= minimumAge) || !std::isfinite(age) || !(largestStretch > 0.0f) ||
    !std::isfinite(largestStretch))
  {
    return 0.0f;
  }
  const double ftle = std::log(double(largestStretch)) / age;
  return std::isfinite(ftle) ? float(ftle) : 0.0f;
}

std::array<float, 3> elementDeformation(
  const StretchFit& fit, const float* positions, double age, bool hidden, double minimumAge)
{
  if (hidden)
  {
    return { 1.0f, 1.0f, 0.0f };
  }
  const std::array<float, 2> s = fit.stretch(positions);
  return { s[0], s[1], elementFtle(s[0], age, minimumAge) };
}

} // namespace bp
