// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TrilinearAlong.h
 * @brief One cell's trilinear interpolation carried with its derivative
 * along a direction, straight from the cell's corners.
 *
 * Moving along a direction q, the fractions f move at g = slope * q, axis by
 * axis (slope_a = d f_a / d x_a), and each lerp a + t (b - a) of the
 * interpolation changes at a' + t (b' - a') + t' (b - a). So the x edges
 * change at g_x times their corners' difference, and two more such levels
 * give (q . grad) v: what a heavy particle's step needs (Inertia.h), at
 * about half the arithmetic of the whole gradient.
 *
 * Written once for T = float (one component: the scalar path) and T = Lanes
 * (the three components in SSE lanes 0-2), so both run the same operations
 * in the same order and give the same bits. The value's operations are
 * VectorField::interpolate's (and interpolateLanes'): the same bits as a
 * plain sample.
 */
#ifndef BoundParticles_TrilinearAlong_h
#define BoundParticles_TrilinearAlong_h

#include "Simd.h"

namespace bp
{

#if BOUNDPARTICLES_SSE2
/// Three components in SSE lanes 0-2 (lane 3 unused), with float's
/// operators applied lane by lane.
struct Lanes
{
  __m128 v;
  Lanes() = default;
  explicit Lanes(__m128 x)
    : v(x)
  {
  }
  explicit Lanes(float s)
    : v(_mm_set1_ps(s))
  {
  }
  /// Three floats into lanes 0-2 (lane 3 is 0), reading no further. The
  /// first two through _mm_loadl_pi, which needs no alignment: floats are
  /// only 4-byte aligned, and _mm_load_sd dereferences a double (UBSan
  /// reports the misaligned load).
  static Lanes load(const float in[3])
  {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(in));
    return Lanes(_mm_movelh_ps(xy, _mm_load_ss(in + 2)));
  }
  /// Lanes 0-2 into out[0..2], writing no further.
  void store(float out[3]) const
  {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), this->v);
    _mm_store_ss(out + 2, _mm_movehl_ps(this->v, this->v));
  }
  /// Lane a in every lane.
  template <int a>
  Lanes broadcast() const
  {
    return Lanes(_mm_shuffle_ps(this->v, this->v, _MM_SHUFFLE(a, a, a, a)));
  }
};
inline Lanes operator+(Lanes a, Lanes b)
{
  return Lanes(_mm_add_ps(a.v, b.v));
}
inline Lanes operator-(Lanes a, Lanes b)
{
  return Lanes(_mm_sub_ps(a.v, b.v));
}
inline Lanes operator*(Lanes a, Lanes b)
{
  return Lanes(_mm_mul_ps(a.v, b.v));
}
#endif

/// One slice's interpolation in a located cell, kept so that its derivative
/// along a direction known only later (it depends on the velocity) takes a
/// few operations more.
template <class T>
struct TrilinearAlong
{
  T step[4];   ///< each x edge's corners' difference, c1 - c0
  T edge[4];   ///< the x edges at fraction f_x: x00, x10, x01, x11
  T across[2]; ///< x10 - x00 and x11 - x01
  T face[2];   ///< the y lerps y0 and y1
  T value;     ///< the interpolated value

  /// Interpolates the corners c000, c100, c010, c110, c001, c101, c011, c111
  /// (x fastest) at fractions f.
  void interpolate(const T c[8], const float f[3])
  {
    const T fx(f[0]), fy(f[1]), fz(f[2]);
    for (int e = 0; e < 4; ++e)
    {
      this->step[e] = c[2 * e + 1] - c[2 * e];
      this->edge[e] = c[2 * e] + fx * this->step[e];
    }
    this->across[0] = this->edge[1] - this->edge[0];
    this->across[1] = this->edge[3] - this->edge[2];
    this->face[0] = this->edge[0] + fy * this->across[0];
    this->face[1] = this->edge[2] + fy * this->across[1];
    this->value = this->face[0] + fz * (this->face[1] - this->face[0]);
  }

  /// The value's derivative along a direction whose fractions move at gx,
  /// gy, gz (g_a = slope_a * q_a), at the fractions f interpolate() used.
  T along(T gx, T gy, T gz, const float f[3]) const
  {
    const T fy(f[1]), fz(f[2]);
    T x[4];
    for (int e = 0; e < 4; ++e)
    {
      x[e] = gx * this->step[e];
    }
    const T y0 = (x[0] + fy * (x[1] - x[0])) + gy * this->across[0];
    const T y1 = (x[2] + fy * (x[3] - x[2])) + gy * this->across[1];
    return (y0 + fz * (y1 - y0)) + gz * (this->face[1] - this->face[0]);
  }
};

} // namespace bp

#endif
