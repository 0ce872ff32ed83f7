// SPDX-License-Identifier: BSD-3-Clause
// Distributed runs without MPI for the core tests: pieces on threads
// exchange elements through memory (TestPartition.cpp, TestEngineState.cpp).
#ifndef BoundParticles_MemoryExchange_h
#define BoundParticles_MemoryExchange_h

#include "Partition.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <vector>

namespace bptest
{

/// A barrier for `count` threads, reusable.
class Barrier
{
public:
  explicit Barrier(int count)
    : Count(count)
  {
  }
  void wait()
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const int generation = this->Generation;
    if (++this->Waiting == this->Count)
    {
      this->Waiting = 0;
      ++this->Generation;
      this->Changed.notify_all();
      return;
    }
    this->Changed.wait(lock, [&] { return generation != this->Generation; });
  }

private:
  std::mutex Mutex;
  std::condition_variable Changed;
  int Count, Waiting = 0, Generation = 0;
};

/// All-to-all through memory for `pieces` threads.
class MemoryExchange
{
public:
  explicit MemoryExchange(int pieces)
    : Sync(pieces)
    , Mail(std::size_t(pieces))
  {
  }
  bp::ExchangeFunction forPiece(int piece)
  {
    return [this, piece](const std::vector<std::vector<std::uint32_t>>& outgoing)
    {
      this->Mail[std::size_t(piece)] = outgoing;
      this->Sync.wait();
      std::vector<std::uint32_t> incoming;
      for (const auto& box : this->Mail)
      {
        const auto& records = box[std::size_t(piece)];
        incoming.insert(incoming.end(), records.begin(), records.end());
      }
      this->Sync.wait(); // nobody overwrites its mail before all have read
      return incoming;
    };
  }

private:
  Barrier Sync;
  std::vector<std::vector<std::vector<std::uint32_t>>> Mail;
};

} // namespace bptest

#endif
