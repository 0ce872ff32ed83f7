// SPDX-License-Identifier: BSD-3-Clause
#include "ValueRanges.h"
#include "Simd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>

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

/**
 * scanAll() for tuples of N components known at compile time: the running
 * ends live in registers and each is one compare-and-select (v < low ? v :
 * low keeps VTK's rule that NaN never wins, and compiles to a min without a
 * branch) instead of a branch per value.
 */
template <typename T, std::size_t N>
void scanTuples(const T* values, std::size_t begin, std::size_t end, Partial<T>& part)
{
  // Two tuples a round into two sets of ends: a min's latency, not its
  // throughput, bounds one chain, so two chains run about twice as fast.
  constexpr std::size_t Lanes = 2;
  T low[Lanes][N], high[Lanes][N], lowSquared[Lanes], highSquared[Lanes];
  for (std::size_t l = 0; l < Lanes; ++l)
  {
    for (std::size_t c = 0; c < N; ++c)
    {
      low[l][c] = std::numeric_limits<T>::max();
      high[l][c] = std::numeric_limits<T>::lowest();
    }
    lowSquared[l] = std::numeric_limits<T>::max();
    highSquared[l] = std::numeric_limits<T>::lowest();
  }
  auto add = [&](std::size_t l, const T* tuple)
  {
    T squaredSum = 0;
    for (std::size_t c = 0; c < N; ++c)
    {
      const T v = tuple[c];
      low[l][c] = v < low[l][c] ? v : low[l][c];
      high[l][c] = v > high[l][c] ? v : high[l][c];
      squaredSum += v * v;
    }
    if constexpr (N > 1)
    {
      lowSquared[l] = squaredSum < lowSquared[l] ? squaredSum : lowSquared[l];
      highSquared[l] = squaredSum > highSquared[l] ? squaredSum : highSquared[l];
    }
  };
  std::size_t i = begin;
  for (; i + Lanes <= end; i += Lanes)
  {
    for (std::size_t l = 0; l < Lanes; ++l)
    {
      add(l, values + N * (i + l));
    }
  }
  for (; i < end; ++i)
  {
    add(0, values + N * i);
  }
  for (std::size_t l = 0; l < Lanes; ++l)
  {
    MinMax<T> lane;
    for (std::size_t c = 0; c < N; ++c)
    {
      lane.low = low[l][c];
      lane.high = high[l][c];
      if (lane.counted())
        part.all[c].merge(lane);
    }
    lane.low = lowSquared[l];
    lane.high = highSquared[l];
    if (N > 1 && lane.counted())
      part.squared.merge(lane);
  }
}

#if BOUNDPARTICLES_SSE2
/// Folds four SSE lanes of running ends into `into` (a lane that saw only
/// NaN has counted nothing).
void foldLanes(__m128 low, __m128 high, MinMax<float>& into)
{
  alignas(16) float lows[4], highs[4];
  _mm_store_ps(lows, low);
  _mm_store_ps(highs, high);
  for (int l = 0; l < 4; ++l)
  {
    MinMax<float> lane;
    lane.low = lows[l];
    lane.high = highs[l];
    if (lane.counted())
      into.merge(lane);
  }
}

/**
 * scanTuples() of float tuples of 1 or 3 components in SSE lanes, four
 * tuples a round. _mm_min_ps(v, low) is v < low ? v : low, the scalar rule
 * (NaN never wins), and a squared magnitude adds x², y², z² in the scalar
 * order, so the ends are the scalar path's bit for bit. Three components are
 * read as 12 floats and transposed to x, y, z registers (lane = tuple).
 */
template <std::size_t N>
void scanFloatTuples(const float* values, std::size_t begin, std::size_t end, Partial<float>& part)
{
  static_assert(N == 1 || N == 3, "lanes for 1 or 3 components");
  const __m128 max = _mm_set1_ps(std::numeric_limits<float>::max());
  const __m128 lowest = _mm_set1_ps(std::numeric_limits<float>::lowest());
  __m128 low[N], high[N], lowSquared = max, highSquared = lowest;
  for (std::size_t c = 0; c < N; ++c)
  {
    low[c] = max;
    high[c] = lowest;
  }
  std::size_t i = begin;
  for (; i + 4 <= end; i += 4)
  {
    const float* t = values + N * i;
    if constexpr (N == 1)
    {
      const __m128 v = _mm_loadu_ps(t);
      low[0] = _mm_min_ps(v, low[0]);
      high[0] = _mm_max_ps(v, high[0]);
    }
    else
    {
      // a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3
      const __m128 a = _mm_loadu_ps(t), b = _mm_loadu_ps(t + 4), c = _mm_loadu_ps(t + 8);
      const __m128 xs = _mm_shuffle_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 2, 3, 0)),
        _mm_shuffle_ps(b, c, _MM_SHUFFLE(1, 1, 2, 2)), _MM_SHUFFLE(2, 0, 1, 0));
      const __m128 ys = _mm_shuffle_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 1, 1)),
        _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 2, 3, 3)), _MM_SHUFFLE(2, 0, 2, 0));
      const __m128 zs = _mm_shuffle_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 1, 2, 2)),
        _mm_shuffle_ps(c, c, _MM_SHUFFLE(3, 3, 0, 0)), _MM_SHUFFLE(2, 0, 2, 0));
      const __m128 v[3] = { xs, ys, zs };
      for (std::size_t k = 0; k < 3; ++k)
      {
        low[k] = _mm_min_ps(v[k], low[k]);
        high[k] = _mm_max_ps(v[k], high[k]);
      }
      const __m128 squared =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(xs, xs), _mm_mul_ps(ys, ys)), _mm_mul_ps(zs, zs));
      lowSquared = _mm_min_ps(squared, lowSquared);
      highSquared = _mm_max_ps(squared, highSquared);
    }
  }
  for (std::size_t c = 0; c < N; ++c)
  {
    foldLanes(low[c], high[c], part.all[c]);
  }
  if constexpr (N > 1)
  {
    foldLanes(lowSquared, highSquared, part.squared);
  }
  scanTuples<float, N>(values, i, end, part); // the last tuples, fewer than four
}
#endif

/// Tuples of N components: in SSE lanes where there is a lane path.
template <typename T, std::size_t N>
void scanTuplesFast(const T* values, std::size_t begin, std::size_t end, Partial<T>& part)
{
#if BOUNDPARTICLES_SSE2
  if constexpr (std::is_same<T, float>::value && (N == 1 || N == 3))
  {
    scanFloatTuples<N>(values, begin, end, part);
    return;
  }
#endif
  scanTuples<T, N>(values, begin, end, part);
}

/// The chunk's ranges of all values; the finite ones copy them, and are
/// computed apart only where an infinity made an end infinite.
template <typename T>
void scanAll(const T* values, std::size_t begin, std::size_t end, std::size_t n, Partial<T>& part)
{
  // The "magnitude" of a 1-component tuple is |v|; VTK uses the component
  // range for it, and so does the caller: none is kept.
  switch (n)
  {
    case 1:
      scanTuplesFast<T, 1>(values, begin, end, part);
      return;
    case 2:
      scanTuples<T, 2>(values, begin, end, part);
      return;
    case 3:
      scanTuplesFast<T, 3>(values, begin, end, part);
      return;
    case 4:
      scanTuples<T, 4>(values, begin, end, part);
      return;
    default:
      break;
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

/// The ranges of tuples [begin, end) into `part`.
template <typename T>
void scanBlock(const T* values, std::size_t begin, std::size_t end, std::size_t n, Partial<T>& part)
{
  Partial<T> found{ static_cast<int>(n) };
  scanAll(values, begin, end, n, found);
  bool infinite = n > 1 && hasInfiniteEnd(found.squared);
  for (const MinMax<T>& m : found.all)
    infinite = infinite || hasInfiniteEnd(m);
  if (infinite)
  {
    scanFinite(values, begin, end, n, found);
  }
  else
  {
    found.finite = found.all; // no infinity in the block
    found.finiteSquared = found.squared;
  }
  part.merge(found);
}

/// The running ranges of one array of a pass, type-erased.
class Scanner
{
public:
  virtual ~Scanner() = default;
  /// Writes tuples [begin, end) (when there is a writer) and takes their ranges.
  virtual void block(std::size_t begin, std::size_t end) = 0;
  /// A new, empty scanner of the same array (one per thread's range).
  virtual std::unique_ptr<Scanner> fresh() const = 0;
  /// Adds what `other` (from fresh()) found.
  virtual void merge(const Scanner& other) = 0;
  virtual ValueRanges ranges() const = 0;
};

template <typename T>
class TypedScanner : public Scanner
{
public:
  TypedScanner(const T* values, int components, const BlockWriter* write)
    : Values(values)
    , Components(components)
    , Write(write)
    , Part(components)
  {
  }
  void block(std::size_t begin, std::size_t end) override
  {
    if (this->Write && *this->Write)
    {
      (*this->Write)(begin, end);
    }
    scanBlock(this->Values, begin, end, std::size_t(this->Components), this->Part);
  }
  std::unique_ptr<Scanner> fresh() const override
  {
    return std::make_unique<TypedScanner>(this->Values, this->Components, this->Write);
  }
  void merge(const Scanner& other) override
  {
    this->Part.merge(static_cast<const TypedScanner&>(other).Part);
  }
  ValueRanges ranges() const override
  {
    ValueRanges r;
    for (std::size_t c = 0; c < std::size_t(this->Components); ++c)
    {
      r.component.push_back(toRange(this->Part.all[c]));
      r.finiteComponent.push_back(toRange(this->Part.finite[c]));
    }
    r.magnitude = rootOf(this->Part.squared);
    r.finiteMagnitude = rootOf(this->Part.finiteSquared);
    return r;
  }

private:
  const T* Values;
  int Components;
  const BlockWriter* Write;
  Partial<T> Part;
};

std::unique_ptr<Scanner> scannerOf(const WrittenArray& a)
{
  if (a.floats)
    return std::make_unique<TypedScanner<float>>(a.floats, a.components, &a.write);
  if (a.doubles)
    return std::make_unique<TypedScanner<double>>(a.doubles, a.components, &a.write);
  if (a.ints)
    return std::make_unique<TypedScanner<int>>(a.ints, a.components, &a.write);
  return std::make_unique<TypedScanner<long long>>(a.longs, a.components, &a.write);
}

void widen(Range& into, const Range& more)
{
  into = { std::min(into[0], more[0]), std::max(into[1], more[1]) };
}

} // namespace

std::vector<ValueRanges> writeTogether(const std::vector<WrittenArray>& arrays, std::size_t tuples,
  std::size_t align, const RangeRunner& run)
{
  align = std::max<std::size_t>(1, align);
  std::vector<std::unique_ptr<Scanner>> total;
  for (const WrittenArray& a : arrays)
  {
    total.push_back(scannerOf(a));
  }
  std::mutex merging;
  // Each range's ranges, merged in the ranges' order once all are done: the
  // same result whichever thread took which range when (a -0 and a 0 are
  // different ends to VTK).
  std::vector<std::pair<std::size_t, std::vector<std::unique_ptr<Scanner>>>> parts;
  // About 2,048 tuples a block: written and scanned while in the core's cache.
  const std::size_t block = std::max<std::size_t>(1, 2048 / align) * align;
  run(tuples / align,
    [&](std::size_t first, std::size_t last)
    {
      std::vector<std::unique_ptr<Scanner>> part;
      for (const auto& t : total)
      {
        part.push_back(t->fresh());
      }
      for (std::size_t begin = first * align; begin < last * align; begin += block)
      {
        const std::size_t end = std::min(begin + block, last * align);
        for (const auto& p : part)
        {
          p->block(begin, end);
        }
      }
      std::lock_guard<std::mutex> lock(merging);
      parts.emplace_back(first, std::move(part));
    });
  std::sort(
    parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& part : parts)
  {
    for (std::size_t k = 0; k < part.second.size(); ++k)
    {
      total[k]->merge(*part.second[k]);
    }
  }
  std::vector<ValueRanges> r;
  for (const auto& t : total)
  {
    r.push_back(t->ranges());
  }
  return r;
}

template <typename T>
ValueRanges valueRanges(const T* values, std::size_t tuples, int components, const RangeRunner& run)
{
  // Nothing is written through the pointer without a writer.
  WrittenArray a;
  a.setValues(const_cast<T*>(values));
  a.components = components;
  return writeTogether({ a }, tuples, 1, run).front();
}

template <typename T>
ValueRanges writeWithRanges(T* values, std::size_t tuples, std::size_t align, int components,
  const RangeRunner& run, const BlockWriter& write)
{
  WrittenArray a;
  a.setValues(values);
  a.components = components;
  a.write = write;
  return writeTogether({ a }, tuples, align, run).front();
}

void mergeRanges(ValueRanges& into, const ValueRanges& more)
{
  // An empty range is {max, lowest}: taking the min and max of the ends
  // leaves the other range as it is.
  for (std::size_t c = 0; c < into.component.size() && c < more.component.size(); ++c)
  {
    widen(into.component[c], more.component[c]);
    widen(into.finiteComponent[c], more.finiteComponent[c]);
  }
  widen(into.magnitude, more.magnitude);
  widen(into.finiteMagnitude, more.finiteMagnitude);
}

template ValueRanges valueRanges<float>(const float*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<double>(const double*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<int>(const int*, std::size_t, int, const RangeRunner&);
template ValueRanges valueRanges<long long>(const long long*, std::size_t, int, const RangeRunner&);

template ValueRanges writeWithRanges<float>(
  float*, std::size_t, std::size_t, int, const RangeRunner&, const BlockWriter&);
template ValueRanges writeWithRanges<double>(
  double*, std::size_t, std::size_t, int, const RangeRunner&, const BlockWriter&);
template ValueRanges writeWithRanges<int>(
  int*, std::size_t, std::size_t, int, const RangeRunner&, const BlockWriter&);
template ValueRanges writeWithRanges<long long>(
  long long*, std::size_t, std::size_t, int, const RangeRunner&, const BlockWriter&);

} // namespace bp
