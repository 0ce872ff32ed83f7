// SPDX-License-Identifier: BSD-3-Clause
#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace bp
{

namespace
{
/**
 * The first exception thrown by any range of one call. An exception must not
 * leave a thread's function (that calls std::terminate, ending the user's
 * session over a bad_alloc), so every range runs under `guard` and the caller
 * rethrows once all of them have ended. The others are dropped: one message
 * ends the update.
 */
class FirstError
{
public:
  template <typename Body>
  void guard(const Body& body) noexcept
  {
    try
    {
      body();
    }
    catch (...)
    {
      // Locked only here, off the path of a call that does not throw.
      std::lock_guard<std::mutex> lock(this->Mutex);
      if (!this->Error)
      {
        this->Error = std::current_exception();
      }
    }
  }
  /// Unlocked: only once every thread that ran a guarded range is done.
  std::exception_ptr take() { return std::exchange(this->Error, nullptr); }

private:
  std::mutex Mutex;
  std::exception_ptr Error;
};
} // namespace

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

namespace
{
class Pool
{
public:
  explicit Pool(unsigned threads)
  {
    this->Workers.reserve(threads - 1);
    try
    {
      for (unsigned w = 1; w < threads; ++w)
      {
        this->Workers.emplace_back([this, w] { this->work(w); });
      }
    }
    catch (...)
    {
      // Out of threads: the workers started so far take the chunks (they
      // read Chunks only once a job, published under Mutex, wakes them).
    }
    this->Chunks = this->Workers.size() + 1;
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
    // Even if the caller's own chunk throws, the workers still use `f` (the
    // caller's) and the pool stays Busy until they are done: wait for them.
    this->Errors.guard([&] { f(0, count / this->Chunks); });
    spinWhile([this] { return this->Pending.load() > 0; });
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->Done.wait(lock, [this] { return this->Pending == 0; });
    }
    // Taken before the pool is free: the next job's errors are its own.
    std::exception_ptr error = this->Errors.take();
    this->Busy = false;
    if (error)
    {
      std::rethrow_exception(error);
    }
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
      this->Errors.guard(
        [&] { (*job)(count * index / this->Chunks, count * (index + 1) / this->Chunks); });
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        --this->Pending;
      }
      this->Done.notify_one();
    }
  }

  std::size_t Chunks = 1;
  std::vector<std::thread> Workers;
  std::atomic<bool> Busy{ false }; ///< while the workers serve a call
  std::mutex Mutex;
  std::condition_variable Wake, Done;
  const RangeFunction* Job = nullptr;
  std::size_t Count = 0;
  FirstError Errors; ///< of the job being served
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
