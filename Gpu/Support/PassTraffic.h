// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PassTraffic.h
 * @brief The memory the GPU engine's passes move at the least, for the
 * benchmarks' bandwidth share: the engine tells it each pass's compulsory
 * traffic (PassObserver::traffic) while it is the engine's observer.
 */
#ifndef BoundParticles_PassTraffic_h
#define BoundParticles_PassTraffic_h

#include "PassObserver.h"

#include <cstddef>
#include <string>

namespace bp
{

/// Usage: engine.setPassObserver(&traffic); one step; engine.setPassObserver(nullptr);
/// then traffic.bytes() is what that step's passes read and wrote.
class PassTraffic : public PassObserver
{
public:
  void begin(const std::string&) override { ++this->Passes; }
  void traffic(std::size_t bytesRead, std::size_t bytesWritten) override
  {
    this->Read += bytesRead;
    this->Written += bytesWritten;
  }
  void end() override {}

  std::size_t bytesRead() const { return this->Read; }
  std::size_t bytesWritten() const { return this->Written; }
  std::size_t bytes() const { return this->Read + this->Written; }
  /// The passes and copies counted.
  long passes() const { return this->Passes; }

private:
  std::size_t Read = 0;
  std::size_t Written = 0;
  long Passes = 0;
};

} // namespace bp

#endif
