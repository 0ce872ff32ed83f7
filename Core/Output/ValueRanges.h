// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ValueRanges.h
 * @brief The ranges VTK keeps for an array (per component and of the tuple
 * magnitude, all values and finite values), computed while the values are
 * still in cache.
 *
 * ParaView asks for every range of every output array after each update (its
 * data information, twice per frame). Computed by VTK that is a pass over each
 * array per range; handed over with the array it is free. The rules are VTK's:
 * NaN never counts; the finite ranges also skip infinities; a tuple's squared
 * magnitude is summed in the array's own value type, and the magnitude range
 * is the square root of the smallest and largest squared magnitude.
 */
#ifndef BoundParticles_ValueRanges_h
#define BoundParticles_ValueRanges_h

#include "Parallel.h"

#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

namespace bp
{

/// [min, max] pairs; min > max when no value counted.
using Range = std::array<double, 2>;

struct ValueRanges
{
  std::vector<Range> component;       ///< NaN skipped
  std::vector<Range> finiteComponent; ///< NaN and infinities skipped
  Range magnitude{ 0, 0 };            ///< of each tuple (2+ components); NaN skipped
  Range finiteMagnitude{ 0, 0 };      ///< infinities skipped as well
};

/// The ranges of `tuples` tuples of `components` values each, in parallel.
template <typename T>
ValueRanges valueRanges(
  const T* values, std::size_t tuples, int components, const RangeRunner& run);

/// Writes tuples [begin, end) of an array; called on disjoint blocks, in parallel.
using BlockWriter = std::function<void(std::size_t begin, std::size_t end)>;

/**
 * Has `write` fill `tuples` tuples of `values` and returns their ranges. It
 * is called on blocks of whole multiples of `align` tuples (`tuples` is one
 * too), small enough to stay in cache, and each block's ranges are taken
 * right after it is written: one pass over the array's memory, not two.
 */
template <typename T>
ValueRanges writeWithRanges(T* values, std::size_t tuples, std::size_t align, int components,
  const RangeRunner& run, const BlockWriter& write);

/// One array of a pass that writes several (writeTogether).
struct WrittenArray
{
  /// Exactly one of these is set: the array's values.
  float* floats = nullptr;
  double* doubles = nullptr;
  int* ints = nullptr;
  long long* longs = nullptr;
  int components = 1;
  BlockWriter write; ///< may be empty: the values are already there

  /// Sets the pointer of T's type.
  template <typename T>
  void setValues(T* values)
  {
    if constexpr (std::is_same<T, float>::value)
      this->floats = values;
    else if constexpr (std::is_same<T, double>::value)
      this->doubles = values;
    else if constexpr (std::is_same<T, int>::value)
      this->ints = values;
    else
    {
      static_assert(std::is_same<T, long long>::value, "float, double, int or long long");
      this->longs = values;
    }
  }
};

/**
 * writeWithRanges() for several arrays of `tuples` tuples in one parallel
 * pass: for each block of whole multiples of `align` tuples, each array in
 * order is written and its block's ranges taken, so a writer may read the
 * same block of an array before it in the list. One round of the threads
 * instead of one per array. Returns the ranges in the arrays' order.
 */
std::vector<ValueRanges> writeTogether(const std::vector<WrittenArray>& arrays, std::size_t tuples,
  std::size_t align, const RangeRunner& run);

/// Widens `into` to hold the values `more` was taken over as well (both of
/// arrays with the same number of components).
void mergeRanges(ValueRanges& into, const ValueRanges& more);

} // namespace bp

#endif
