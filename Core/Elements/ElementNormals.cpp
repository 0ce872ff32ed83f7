// SPDX-License-Identifier: BSD-3-Clause
#include "ElementNormals.h"
#include "Simd.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace bp
{
namespace
{
/// Particles whose sums fit the stack buffers.
constexpr std::size_t LocalParticles = 64;

/// elementNormals() accumulating in `sum` (3n floats, not aliasing p or nr:
/// stores into nr could alias p for the compiler, which would then reload
/// every corner after every store).
void elementNormalsVia(
  const ElementTemplate& shape, const float* p, float* __restrict sum, float* nr)
{
  const std::size_t n = shape.particleCount();
  std::fill_n(sum, 3 * n, 0.0f);
  for (const auto& tri : shape.triangles)
  {
    const float* a = p + 3 * tri[0];
    const float* b = p + 3 * tri[1];
    const float* c = p + 3 * tri[2];
    const float u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const float v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const float x[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const float len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!(len > 0.0f))
    {
      continue;
    }
    const float inverse = 1.0f / len;
    for (std::uint32_t idx : tri)
    {
      for (int k = 0; k < 3; ++k)
      {
        sum[3 * idx + k] += x[k] * inverse;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const float* q = sum + 3 * i;
    const float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    float* out = nr + 3 * i;
    if (len > 0.0f)
    {
      const float inverse = 1.0f / len;
      out[0] = q[0] * inverse;
      out[1] = q[1] * inverse;
      out[2] = q[2] * inverse;
    }
    else
    {
      // No (non-degenerate) triangle: a fixed normal keeps the output finite.
      out[0] = 0.0f;
      out[1] = 0.0f;
      out[2] = 1.0f;
    }
  }
}

#if BOUNDPARTICLES_SSE2
/**
 * elementNormalsVia() for four consecutive elements, one per lane: the same
 * IEEE operations in the same order (SSE2, no fused multiply-add), so the
 * same bits. A sqrt and a division per triangle wait on each other; four
 * lanes share the wait. `sum` holds 12n floats: (3i + k) * 4 + lane.
 */
void fourElementNormals(
  const ElementTemplate& shape, const float* p, float* __restrict sum, float* nr)
{
  const std::size_t n = shape.particleCount(), stride = 3 * n;
  std::fill_n(sum, 12 * n, 0.0f);
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  auto lanes = [&](std::size_t at)
  { return _mm_setr_ps(p[at], p[stride + at], p[2 * stride + at], p[3 * stride + at]); };
  for (const auto& tri : shape.triangles)
  {
    __m128 corner[3][3];
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        corner[j][k] = lanes(3 * std::size_t(tri[std::size_t(j)]) + std::size_t(k));
      }
    }
    __m128 u[3], v[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = _mm_sub_ps(corner[1][k], corner[0][k]);
      v[k] = _mm_sub_ps(corner[2][k], corner[0][k]);
    }
    const __m128 x[3] = { _mm_sub_ps(_mm_mul_ps(u[1], v[2]), _mm_mul_ps(u[2], v[1])),
      _mm_sub_ps(_mm_mul_ps(u[2], v[0]), _mm_mul_ps(u[0], v[2])),
      _mm_sub_ps(_mm_mul_ps(u[0], v[1]), _mm_mul_ps(u[1], v[0])) };
    const __m128 len = _mm_sqrt_ps(_mm_add_ps(
      _mm_add_ps(_mm_mul_ps(x[0], x[0]), _mm_mul_ps(x[1], x[1])), _mm_mul_ps(x[2], x[2])));
    // A lane whose triangle is skipped adds +0, which changes no sum (a sum
    // that starts at +0 is never -0).
    const __m128 counted = _mm_cmpgt_ps(len, zero);
    const __m128 inverse = _mm_div_ps(one, len);
    __m128 unit[3];
    for (int k = 0; k < 3; ++k)
    {
      unit[k] = _mm_and_ps(counted, _mm_mul_ps(x[k], inverse));
    }
    for (std::uint32_t idx : tri)
    {
      for (int k = 0; k < 3; ++k)
      {
        float* s = sum + 4 * (3 * std::size_t(idx) + std::size_t(k));
        _mm_storeu_ps(s, _mm_add_ps(_mm_loadu_ps(s), unit[k]));
      }
    }
  }
  const __m128 up[3] = { zero, zero, one };
  for (std::size_t i = 0; i < n; ++i)
  {
    __m128 q[3];
    for (int k = 0; k < 3; ++k)
    {
      q[k] = _mm_loadu_ps(sum + 4 * (3 * i + std::size_t(k)));
    }
    const __m128 len = _mm_sqrt_ps(_mm_add_ps(
      _mm_add_ps(_mm_mul_ps(q[0], q[0]), _mm_mul_ps(q[1], q[1])), _mm_mul_ps(q[2], q[2])));
    const __m128 counted = _mm_cmpgt_ps(len, zero);
    const __m128 inverse = _mm_div_ps(one, len);
    alignas(16) float out[3][4];
    for (int k = 0; k < 3; ++k)
    {
      const __m128 scaled = _mm_mul_ps(q[k], inverse);
      _mm_store_ps(out[k], _mm_or_ps(_mm_and_ps(counted, scaled), _mm_andnot_ps(counted, up[k])));
    }
    for (std::size_t lane = 0; lane < 4; ++lane)
    {
      for (int k = 0; k < 3; ++k)
      {
        nr[lane * stride + 3 * i + std::size_t(k)] = out[k][lane];
      }
    }
  }
}
#endif
} // namespace

void elementNormals(const ElementTemplate& shape, const float* p, float* nr)
{
  const std::size_t n = shape.particleCount();
  if (n <= LocalParticles)
  {
    float sum[3 * LocalParticles];
    elementNormalsVia(shape, p, sum, nr);
  }
  else
  {
    std::vector<float> sum(3 * n);
    elementNormalsVia(shape, p, sum.data(), nr);
  }
}

void elementsNormals(
  const ElementTemplate& shape, const float* positions, float* normals, std::size_t count)
{
  const std::size_t n = shape.particleCount(), stride = 3 * n;
  std::size_t e = 0;
#if BOUNDPARTICLES_SSE2
  float local[12 * LocalParticles];
  std::vector<float> large(n > LocalParticles ? 12 * n : 0);
  float* sum = n > LocalParticles ? large.data() : local;
  for (; e + 4 <= count; e += 4)
  {
    fourElementNormals(shape, positions + e * stride, sum, normals + e * stride);
  }
#endif
  for (; e < count; ++e)
  {
    elementNormals(shape, positions + e * stride, normals + e * stride);
  }
}

} // namespace bp
