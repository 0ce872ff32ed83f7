// SPDX-License-Identifier: BSD-3-Clause
#include "StreamTimeLine.h"

#include <cmath>
#include <sstream>

namespace bp
{

StreamTimeLine::Arrival StreamTimeLine::offer(double time)
{
  if (!std::isfinite(time))
  {
    return Arrival::Back;
  }
  if (this->Times.empty())
  {
    this->Times.push_back(time);
    return Arrival::Start;
  }
  if (time == this->Times.back())
  {
    return Arrival::Repeat;
  }
  if (time < this->Times.back())
  {
    return Arrival::Back;
  }
  this->Times.push_back(time);
  return Arrival::Advance;
}

std::string StreamTimeLine::refusal(Arrival arrival, double time) const
{
  if (arrival != Arrival::Repeat && arrival != Arrival::Back)
  {
    return std::string();
  }
  std::ostringstream text;
  text << "The input's present time step (t = " << time << ") ";
  if (!std::isfinite(time))
  {
    text << "is not finite";
  }
  else
  {
    text << (arrival == Arrival::Repeat ? "repeats the last one" : "comes before the last one")
         << " (t = " << this->present() << ")";
  }
  text << "; the step is refused and the trace stays at t = " << this->present()
       << ". Each step handed in situ must come later than the one before.";
  return text.str();
}

void StreamTimeLine::restartAtPresent()
{
  if (this->Times.size() > 1)
  {
    this->Times.erase(this->Times.begin(), this->Times.end() - 1);
  }
}

void StreamTimeLine::dropPresent()
{
  if (!this->Times.empty())
  {
    this->Times.pop_back();
  }
}

} // namespace bp
