// SPDX-License-Identifier: BSD-3-Clause
#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
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

namespace
{
class Pool
{
public:
  explicit Pool(unsigned threads)
    : Chunks(threads)
  {
    for (unsigned w = 1; w < threads; ++w)
    {
      this->Workers.emplace_back([this, w] { this->work(w); });
    }
  }
  ~Pool()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stop = true;
      ++this->Generation;
    }
    this->Wake.notify_all();
    for (auto& t : this->Workers)
    {
      t.join();
    }
  }
  void run(std::size_t count, const RangeFunction& f)
  {
    // A call from inside a job (nested) or from a second thread while the
    // workers are busy runs on its caller alone rather than wait for them.
    bool idle = false;
    if (this->Workers.empty() || count < this->Chunks ||
      !this->Busy.compare_exchange_strong(idle, true))
    {
      if (count > 0)
      {
        f(0, count);
      }
      return;
    }
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Job = &f;
      this->Count = count;
      this->Pending = this->Workers.size();
      ++this->Generation;
    }
    this->Wake.notify_all();
    f(0, count / this->Chunks); // the caller's own chunk
    spinWhile([this] { return this->Pending.load() > 0; });
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Done.wait(lock, [this] { return this->Pending == 0; });
    this->Busy = false;
  }

private:
  /**
   * Waits up to SpinTime while `busy()` holds, awake: the tracer's loops
   * come in bursts (a step's phases, the output's arrays one after another),
   * and a thread woken from sleep starts tens of microseconds late, which
   * cost a 4,096-element update about a tenth of its time (issue 16).
   */
  template <typename Busy>
  static void spinWhile(const Busy& busy)
  {
    constexpr auto SpinTime = std::chrono::microseconds(50);
    const auto until = std::chrono::steady_clock::now() + SpinTime;
    while (busy())
    {
      for (int k = 0; k < 64 && busy(); ++k)
      {
        std::this_thread::yield();
      }
      if (std::chrono::steady_clock::now() > until)
      {
        return;
      }
    }
  }

  void work(unsigned index)
  {
    std::size_t seen = 0;
    while (true)
    {
      const RangeFunction* job;
      std::size_t count;
      spinWhile([&] { return this->Generation.load() == seen; });
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        this->Wake.wait(lock, [&] { return this->Generation != seen; });
        seen = this->Generation;
        if (this->Stop)
        {
          return;
        }
        job = this->Job;
        count = this->Count;
      }
      (*job)(count * index / this->Chunks, count * (index + 1) / this->Chunks);
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        --this->Pending;
      }
      this->Done.notify_one();
    }
  }

  const std::size_t Chunks;
  std::vector<std::thread> Workers;
  std::atomic<bool> Busy{ false }; ///< while the workers serve a call
  std::mutex Mutex;
  std::condition_variable Wake, Done;
  const RangeFunction* Job = nullptr;
  std::size_t Count = 0;
  /// Changed under Mutex; atomic so that spinning threads may read them unlocked.
  std::atomic<std::size_t> Pending{ 0 }, Generation{ 0 };
  bool Stop = false;
};
} // namespace

RangeRunner poolRunner(unsigned threads)
{
  auto pool = std::make_shared<Pool>(std::max(1u, threads));
  return [pool](std::size_t count, const RangeFunction& f) { pool->run(count, f); };
}

} // namespace bp
