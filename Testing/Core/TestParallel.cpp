// SPDX-License-Identifier: BSD-3-Clause
// A range that throws must end the call on its caller, never the process, and
// leave the runner as it was: the filter's loops allocate, and a bad_alloc in
// one ends the update with a message.
#include "Parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <new>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
constexpr unsigned Threads = 4;
constexpr std::size_t Count = 4000;

/// How often each item was visited, and by which threads.
struct Tally
{
  std::vector<int> hits = std::vector<int>(Count, 0);
  std::mutex mutex;
  std::set<std::thread::id> threads;

  void visit(std::size_t begin, std::size_t end)
  {
    for (std::size_t i = begin; i < end; ++i)
      ++this->hits[i];
    std::lock_guard<std::mutex> lock(this->mutex);
    this->threads.insert(std::this_thread::get_id());
  }
  bool everyItemOnce() const
  {
    return std::count(this->hits.begin(), this->hits.end(), 1) == std::ptrdiff_t(Count);
  }
};

/// Workers that finish well after the caller's chunk: a call that returned
/// early would not have seen their visits.
void late()
{
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

/// After a throw the runner serves the next call in full, a pool on all its
/// threads (a pool left busy would run it on the caller alone); `threads` 0:
/// not checked (std::thread ids of ended threads may come back).
void expectAFullCall(const bp::RangeRunner& run, std::size_t threads)
{
  Tally tally;
  run(Count, [&](std::size_t begin, std::size_t end) { tally.visit(begin, end); });
  EXPECT_TRUE(tally.everyItemOnce());
  if (threads > 0)
  {
    EXPECT_EQ(tally.threads.size(), threads);
  }
}
} // namespace

TEST(Parallel, APoolRethrowsItsCallersExceptionOnceEveryChunkHasEnded)
{
  const bp::RangeRunner run = bp::poolRunner(Threads);
  const std::thread::id caller = std::this_thread::get_id();
  Tally tally;
  try
  {
    run(Count,
      [&](std::size_t begin, std::size_t end)
      {
        if (std::this_thread::get_id() == caller)
        {
          tally.visit(begin, end);
          throw std::runtime_error("caller");
        }
        late();
        tally.visit(begin, end);
      });
    ADD_FAILURE() << "nothing thrown";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_STREQ(e.what(), "caller");
  }
  EXPECT_TRUE(tally.everyItemOnce());
  expectAFullCall(run, Threads);
}

TEST(Parallel, APoolRethrowsAWorkersExceptionOnItsCaller)
{
  const bp::RangeRunner run = bp::poolRunner(Threads);
  const std::thread::id caller = std::this_thread::get_id();
  Tally tally;
  std::thread::id thrower = caller;
  try
  {
    run(Count,
      [&](std::size_t begin, std::size_t end)
      {
        tally.visit(begin, end);
        if (begin == Count / Threads)
        {
          thrower = std::this_thread::get_id();
          throw std::runtime_error("worker");
        }
      });
    ADD_FAILURE() << "nothing thrown";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_STREQ(e.what(), "worker");
  }
  EXPECT_NE(thrower, caller);
  EXPECT_TRUE(tally.everyItemOnce());
  expectAFullCall(run, Threads);
}

TEST(Parallel, BadAllocInAnyChunkEndsTheCallNotTheProcess)
{
  const bp::RangeRunner runners[] = { bp::serialRunner(), bp::poolRunner(Threads) };
  for (int r = 0; r < 2; ++r)
  {
    // The first chunk is the pool's caller's, the last a worker's.
    for (bool first : { true, false })
    {
      SCOPED_TRACE("runner " + std::to_string(r) + (first ? " first" : " last") + " chunk");
      Tally tally;
      EXPECT_THROW(runners[r](Count,
                     [&](std::size_t begin, std::size_t end)
                     {
                       tally.visit(begin, end);
                       if (first ? begin == 0 : end == Count)
                         throw std::bad_alloc();
                       late();
                     }),
        std::bad_alloc);
      EXPECT_TRUE(tally.everyItemOnce());
      expectAFullCall(runners[r], r == 1 ? Threads : 1);
    }
  }
}

TEST(Parallel, OfExceptionsFromEveryChunkOneComesOut)
{
  const bp::RangeRunner run = bp::poolRunner(Threads);
  // Many rounds: the chunks throw at once, in whatever order.
  for (int round = 0; round < 50; ++round)
  {
    Tally tally;
    std::string message;
    try
    {
      run(Count,
        [&](std::size_t begin, std::size_t end)
        {
          tally.visit(begin, end);
          throw std::runtime_error(std::to_string(begin));
        });
    }
    catch (const std::runtime_error& e)
    {
      message = e.what();
    }
    bool fromAChunk = false;
    for (std::size_t c = 0; c < Threads; ++c)
      fromAChunk = fromAChunk || message == std::to_string(Count * c / Threads);
    EXPECT_TRUE(fromAChunk) << "'" << message << "'";
    EXPECT_TRUE(tally.everyItemOnce());
  }
  expectAFullCall(run, Threads);
}

TEST(Parallel, AThrowInANestedPoolCallReachesTheOuterCaller)
{
  // A nested call runs on its caller, here a worker: its exception leaves
  // the worker's chunk of the outer call and comes out of the outer call.
  const bp::RangeRunner run = bp::poolRunner(Threads);
  Tally tally;
  EXPECT_THROW(run(Count,
                 [&](std::size_t begin, std::size_t end)
                 {
                   run(end - begin,
                     [&, begin](std::size_t b, std::size_t e)
                     {
                       tally.visit(begin + b, begin + e);
                       if (begin + e == Count)
                         throw std::out_of_range("nested");
                     });
                 }),
    std::out_of_range);
  EXPECT_TRUE(tally.everyItemOnce());
  expectAFullCall(run, Threads);
}
