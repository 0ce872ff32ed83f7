// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ElementStretch.h
 * @brief How much an element is stretched against its template, and the
 * finite-time Lyapunov exponent that follows from it.
 *
 * The ElementStretch and ElementFTLE output arrays, and the tracer's FTLE
 * map, all come from here, for both engines' states (the GPU engine's tests
 * read its positions back and apply the same fit). The fit is linear shape
 * matching's best linear map F of the template onto the particles, both
 * about their means: F = A Aqq^-1 with A = sum (p - pbar)(q - qbar)^T and
 * Aqq = sum (q - qbar)(q - qbar)^T. A flat or straight template spans fewer
 * than three directions: F is then taken over that span alone (Aqq's
 * pseudo-inverse) and its singular values there are the stretches.
 */
#ifndef BoundParticles_ElementStretch_h
#define BoundParticles_ElementStretch_h

#include <array>
#include <vector>

namespace bp
{

/**
 * @class StretchFit
 * @brief The part of the fit that depends only on the template: its mean and
 * Aqq's pseudo-inverse over its span, so that each element costs one pass
 * over its particles and a 3x3 eigenproblem.
 */
class StretchFit
{
public:
  /// `rest`: the template's rest positions; `size`: the element size they
  /// are scaled by (the stretches do not depend on it, but the fit is made
  /// at the scale the engine places elements at).
  StretchFit(const std::vector<std::array<float, 3>>& rest, double size);

  /// The largest and smallest principal stretch of the element whose `n`
  /// particles start at `positions` (3 floats each, in template order):
  /// (1, 1) for a template that spans nothing (one particle) or positions
  /// that are not finite.
  std::array<float, 2> stretch(const float* positions) const;

  /// How many directions the template spans (0 to 3).
  int span() const { return this->Span; }

  /// The rest positions about their mean, scaled by the size, in template
  /// order: what the GPU display's draw shader fits against.
  const std::vector<std::array<double, 3>>& centred() const { return this->Centred; }
  /// Aqq^+ over the span (row-major; symmetric), for the same fit on the GPU.
  const double* restMomentPseudoInverse() const { return this->B; }

private:
  std::vector<std::array<double, 3>> Centred; ///< rest positions about their mean, scaled
  double B[9] = {};                           ///< Aqq^+ (row-major), over the span
  int Span = 0;
};

/// The steps an element must have been traced for before it has an FTLE
/// (Parameters::ftleMinimumAge is this many of the trace's steps). Over a
/// shorter age ln(stretch) / age is ill-conditioned: the deformation the
/// springs leave of the last steps (a few percent for a stiff element in
/// strong strain), divided by an age of a step or two, read up to 437 on
/// the combustor where grown elements read 5 to 30.
constexpr int MinimumFtleSteps = 10;

/// ln(largest stretch) / age: 0 where the age is not positive, is below
/// `minimumAge`, or either is not finite (an element just placed has no
/// exponent yet).
float elementFtle(float largestStretch, double age, double minimumAge = 0.0);

/// What the output shows of one element: its largest and smallest stretch
/// and its FTLE over `age` (0 below `minimumAge`); (1, 1, 0) for an element
/// not yet released (`hidden`), which shows nothing.
std::array<float, 3> elementDeformation(
  const StretchFit& fit, const float* positions, double age, bool hidden, double minimumAge = 0.0);

} // namespace bp

#endif
