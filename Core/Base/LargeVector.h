// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file LargeVector.h
 * @brief assignLarge: sizes the engine's per-element arrays in memory the
 * system may back with huge pages.
 */
#ifndef BoundParticles_LargeVector_h
#define BoundParticles_LargeVector_h

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bp
{

/**
 * Sizes v to `count` copies of `value` in memory the system may back with
 * huge pages: a step visits elements in space order, not memory order, and
 * with 4 KiB pages nearly every element's state would miss the TLB.
 */
template <class T>
void assignLarge(std::vector<T>& v, std::size_t count, T value)
{
  std::vector<T>().swap(v);
  v.reserve(count);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t Huge = std::uintptr_t(2) << 20;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (begin + Huge - 1) & ~(Huge - 1);
  const std::uintptr_t last = (begin + count * sizeof(T)) & ~(Huge - 1);
  if (last > first)
  {
    // Advice only: where it is refused the pages are ordinary.
    madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#endif
  v.assign(count, value);
}

} // namespace bp

#endif
