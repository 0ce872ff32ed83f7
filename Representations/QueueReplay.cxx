// SPDX-License-Identifier: BSD-3-Clause
// Runs a work queue's engine calls on the display's GPU engine (QueueReplay.h).
#include "QueueReplay.h"

#include "EngineCall.h"
#include "ReplayProgress.h"

namespace bpvtk
{

void QueueReplay::run(
  const std::vector<bp::EngineCall>& calls, bp::ReplayProgress& progress, const Listener& listener)
{
  for (std::size_t k = 0; k < calls.size() && progress.beforeCall(k); ++k)
  {
    const bp::EngineCall& call = calls[k];
    const bool configure = call.kind == bp::EngineCall::Kind::Configure;
    if (configure)
    {
      this->Failed = false;
      this->Configured = false;
    }
    else if (!this->Configured || this->Failed)
    {
      continue; // what follows a failed call would continue from nothing
    }
    const std::string error = call.applyTo(this->Stepper);
    if (!error.empty())
    {
      this->Failed = true;
      const bool load = call.kind == bp::EngineCall::Kind::LoadState;
      listener.failed(std::string(configure ? "The GPU engine cannot run this trace: "
                          : load            ? "The GPU engine cannot resume this state: "
                                            : "The GPU engine cannot hold this field: ") +
        error + ". This display draws the CPU result from the next update on.");
    }
    else if (configure)
    {
      this->Configured = true;
      listener.configured(call);
    }
  }
}

} // namespace bpvtk
