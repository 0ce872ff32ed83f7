// SPDX-License-Identifier: BSD-3-Clause
#include "BoundParticleWorkQueues.h"

#include "WorkQueue.h"

#include <map>
#include <mutex>

namespace
{
std::mutex& registryMutex()
{
  static std::mutex m;
  return m;
}
std::map<int, std::weak_ptr<bp::WorkQueue>>& registry()
{
  static std::map<int, std::weak_ptr<bp::WorkQueue>> r;
  return r;
}
} // namespace

namespace bpvtk
{

bp::DisplayWorkQueue NewWorkQueue()
{
  std::lock_guard<std::mutex> lock(registryMutex());
  static int nextId = 0;
  auto& queues = registry();
  for (auto it = queues.begin(); it != queues.end();)
    it = it->second.expired() ? queues.erase(it) : std::next(it);
  std::shared_ptr<bp::WorkQueue> recorder;
  bp::DisplayWorkQueue made = bp::newDisplayWorkQueue(++nextId, recorder);
  queues[recorder->id()] = recorder;
  return made;
}

std::shared_ptr<bp::WorkQueue> FindWorkQueue(int id)
{
  std::lock_guard<std::mutex> lock(registryMutex());
  const auto it = registry().find(id);
  return it == registry().end() ? nullptr : it->second.lock();
}

} // namespace bpvtk
