// SPDX-License-Identifier: BSD-3-Clause
#include "ValueRanges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>

namespace bp
{
namespace
{

template <typename T>
bool isInfinite(T value)
{
  if constexpr (std::numeric_limits<T>::has_infinity)
  {
    return std::isinf(value);
  }
  else
  {
    return false;
  }
}

/// Running [min, max] of one quantity in T, as VTK keeps it (NaN never wins
/// a comparison, so it is never taken).
template <typename T>
struct MinMax
{
  T low = std::numeric_limits<T>::max();
  T high = std::numeric_limits<T>::lowest();
  void add(T v)
  {
    if (v < low)
      low = v;
    if (v > high)
      high = v;
  }
  void merge(const MinMax& o)
  {
    add(o.low);
    add(o.high);
  }
  bool counted() const { return !(low > high); }
};

/// What one chunk of tuples found.
template <typename T>
struct Partial
{
  std::vector<MinMax<T>> all, finite;
  MinMax<T> squared, finiteSquared;
  explicit Partial(int components)
    : all(std::size_t(components))
    , finite(std::size_t(components))
  {
  }
  void merge(const Partial& o)
  {
    for (std::size_t c = 0; c < all.size(); ++c)
    {
      if (o.all[c].counted())
        all[c].merge(o.all[c]);
      if (o.finite[c].counted())
        finite[c].merge(o.finite[c]);
    }
    if (o.squared.counted())
      squared.merge(o.squared);
    if (o.finiteSquared.counted())
      finiteSquared.merge(o.finiteSquared);
  }
};

template <typename T>
Range toRange(const MinMax<T>& m)
{
  return m.counted()
    ? Range{ double(m.low), double(m.high) }
    : Range{ std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
}

template <typename T>
Range rootOf(const MinMax<T>& m)
{
  Range r = toRange(m);
  return m.counted() ? Range{ std::sqrt(r[0]), std::sqrt(r[1]) } : r;
}

/// The chunk's ranges of all values; the finite ones copy them, and are
/// computed apart only where an infinity made an end infinite.
template <typename T>
void scanAll(const T* values, std::size_t begin, std::size_t end, std::size_t n, Partial<T>& part)
{
  if (n == 1)
  {
    MinMax<T> m;
    for (std::size_t i = begin; i < end; ++i)
    {
      m.add(values[i]);
      // The "magnitude" of a 1-component tuple is |v|; VTK uses the
      // component range for it, and so does the caller.
    }
    part.all[0] = m;
    return;
  }
  for (std::size_t i = begin; i < end; ++i)
  {
    const T* tuple = values + n * i;
    T squaredSum = 0;
    for (std::size_t c = 0; c < n; ++c)
    {
      const T v = tuple[c];
      part.all[c].add(v);
      squaredSum += v * v;
    }
    part.squared.add(squaredSum);
  }
}

template <typename T>
bool hasInfiniteEnd(const MinMax<T>& m)
{
  return m.counted() && (isInfinite(m.low) || isInfinite(m.high));
}

/// The finite ranges of a chunk whose plain ranges reached an infinity.
template <typename T>
void scanFinite(
  const T* values, std::size_t begin, std::size_t end, std::size_t n, Partial<T>& part)
{
  for (std::size_t i = begin; i < end; ++i)
  {
    const T* tuple = values + n * i;
    T squaredSum = 0;
    for (std::size_t c = 0; c < n; ++c)
    {
      const T v = tuple[c];
      if (!isInfinite(v))
        part.finite[c].add(v);
      squaredSum += v * v;
    }
    if (!isInfinite(squaredSum))
      part.finiteSquared.add(squaredSum);
  }
}

} // namespace

template <typename T>
ValueRanges valueRanges(const T* values, std::size_t tuples, int components, const RangeRunner& run)
{
  Partial<T> total(components);
  std::mutex merging;
  const std::size_t n = std::size_t(components);
  run(tuples,
    [&](std::size_t begin, std::size_t end)
    {
      Partial<T> part(components);
      scanAll(values, begin, end, n, part);
      bool infinite = n > 1 && hasInfiniteEnd(part.squared);
      for (const MinMax<T>& m : part.all)
        infinite = infinite || hasInfiniteEnd(m);
      if (infinite)
      {
        scanFinite(values, begin, end, n, part);
      }
      else
      {
        part.finite = part.all; // no infinity in the chunk
        part.finiteSquared = part.squared;
      }
      std::lock_guard<std::mutex> lock(merging);
      total.merge(part);
    });
  ValueRanges r;
  for (std::size_t c = 0; c < n; ++c)
  {
    r.component.push_back(toRange(total.all[c]));
    r.finiteComponent.push_back(toRange(total.finite[c]));
  }
  r.magnitude = rootOf(total.squared);
  r.finiteMagnitude = rootOf(total.finiteSquared);
  return r;
}

template ValueRanges valueRanges<float>(const float*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<double>(const double*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<int>(const int*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<long long>(const long long*, std::size_t, int, const RangeRunner&);

} // namespace bp
