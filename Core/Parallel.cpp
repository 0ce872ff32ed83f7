// SPDX-License-Identifier: BSD-3-Clause
#include "Parallel.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace bp
{

RangeRunner serialRunner()
{
  return [](std::size_t count, const RangeFunction& f)
  {
    if (count > 0)
    {
      f(0, count);
    }
  };
}

RangeRunner threadRunner(unsigned threads)
{
  threads = std::max(1u, threads);
  return [threads](std::size_t count, const RangeFunction& f)
  {
    const std::size_t chunks = std::min<std::size_t>(threads, count);
    if (chunks <= 1)
    {
      if (count > 0)
      {
        f(0, count);
      }
      return;
    }
    std::vector<std::thread> workers;
    workers.reserve(chunks);
    for (std::size_t c = 0; c < chunks; ++c)
    {
      const std::size_t begin = count * c / chunks;
      const std::size_t end = count * (c + 1) / chunks;
      workers.emplace_back([&f, begin, end] { f(begin, end); });
    }
    for (auto& w : workers)
    {
      w.join();
    }
  };
}

} // namespace bp
