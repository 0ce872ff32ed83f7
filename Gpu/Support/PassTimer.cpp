// SPDX-License-Identifier: BSD-3-Clause
#include "PassTimer.h"

#include "RendererKind.h"

#include <algorithm>
#include <chrono>

namespace bp
{
namespace
{
/// Pending queries beyond this are read (the oldest, long finished), so a
/// long timed run holds a bounded number.
constexpr std::size_t MostPending = 4096;

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

void PassTimer::enable(bool on)
{
  if (!on)
  {
    this->settle(0);
    this->Times.clear();
    this->Free.clear();
    this->Queries.clear();
  }
  else if (!this->On)
  {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    this->CpuClock = rendererKind(renderer ? renderer : "") == RendererKind::Software;
  }
  this->On = on;
}

void PassTimer::begin(const std::string& pass)
{
  if (!this->On)
  {
    return;
  }
  const auto known = std::find_if(this->Times.begin(), this->Times.end(),
    [&](const PassTime& time) { return time.pass == pass; });
  const std::size_t index = std::size_t(known - this->Times.begin());
  if (known == this->Times.end())
  {
    this->Times.push_back({ pass, 0, 0.0 });
  }
  if (this->CpuClock)
  {
    glFinish(); // what came before runs outside this pass's time
    this->Running = index;
    this->Started = now();
    return;
  }
  if (this->Open.size() >= MostPending)
  {
    this->settle(MostPending / 2);
  }
  if (this->Free.empty())
  {
    GLuint name = 0;
    glGenQueries(1, &name);
    this->Queries.add(GlQuery(name));
    this->Free.push_back(this->Queries.size() - 1);
  }
  const std::size_t query = this->Free.back();
  this->Free.pop_back();
  this->Open.push_back({ query, index });
  glBeginQuery(GL_TIME_ELAPSED, this->Queries[query]);
}

void PassTimer::end()
{
  if (this->On && this->CpuClock)
  {
    glFinish(); // the pass itself, run now on a software renderer
    PassTime& time = this->Times[this->Running];
    ++time.runs;
    time.seconds += now() - this->Started;
  }
  else if (this->On)
  {
    glEndQuery(GL_TIME_ELAPSED);
  }
}

void PassTimer::settle(std::size_t keep)
{
  while (this->Open.size() > keep)
  {
    const Pending pending = this->Open.front();
    this->Open.pop_front();
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(this->Queries[pending.query], GL_QUERY_RESULT, &nanoseconds);
    PassTime& time = this->Times[pending.pass];
    ++time.runs;
    time.seconds += 1e-9 * double(nanoseconds);
    this->Free.push_back(pending.query);
  }
}

std::vector<PassTime> PassTimer::collect()
{
  this->settle(0);
  std::vector<PassTime> out;
  out.swap(this->Times);
  return out;
}

} // namespace bp
