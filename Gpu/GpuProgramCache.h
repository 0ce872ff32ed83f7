// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuProgramCache.h
 * @brief The GPU engine's programs, each compiled once for its source and
 * kept across configure().
 *
 * A program is specialised at compile time (GpuPasses.h,
 * KernelSpecialisation): the kernels that use the integrator, heavy
 * particles or the poses are compiled with #defines for them, not branched
 * on uniforms. A trace whose settings change (the filter's Integrator,
 * Inertia or Trails mid-session) configures the engine again, and each
 * configure asks this cache for its programs: one whose source (path, the
 * #defines of its kernel and specialisation, every file's text) was compiled
 * before is that program again, so no program is compiled twice for the
 * same source, and the programs that do not depend on a setting are shared
 * by every setting. A program taken from the cache starts as a fresh one
 * does: every uniform of its default block 0, its images' units left as
 * their layout binds them.
 *
 * The cache owns its programs (GlObjects.h): clear() deletes them, with
 * the context current (GpuEngine::release); beginUse() deletes, beyond
 * MostKept, those handed out the longest ago. A system holds their names
 * only.
 */
#ifndef BoundParticles_GpuProgramCache_h
#define BoundParticles_GpuProgramCache_h

#include "GlObjects.h"
#include "GpuPath.h"
#include "ShaderSource.h"

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace bp
{

class GpuProgramCache
{
public:
  /// Programs kept: a fragment and a compute set (15 and 16 programs) and
  /// a few specialisations of the ones that depend on a setting.
  static constexpr std::size_t MostKept = 64;

  /// buildProgram()'s program for these arguments, its name into `out`:
  /// compiled and linked the first time its source is asked for, the same
  /// program (its uniforms set to 0) every later time. Empty on success,
  /// otherwise buildProgram()'s log and `out` 0 (a program that fails is
  /// not kept). Needs the context current.
  std::string build(GpuPath path, const std::string& name, const std::string& defines,
    const std::vector<ShaderPiece>& pieces, GLuint& out, bool images = false);

  /// Starts a configure, when no program is in use (the last system is
  /// gone): beyond MostKept programs, deletes those handed out the longest
  /// ago; the needs of several configures before are kept (MostKept holds
  /// four systems' programs). Needs the context current.
  void beginUse();

  /// Programs compiled since the cache was made or cleared.
  long compiles() const { return this->Compiles; }
  /// Programs kept.
  std::size_t size() const { return this->Programs.size(); }

  /// Deletes every program; the context must be current.
  void clear();

private:
  struct Entry
  {
    GlProgram program;
    long lastUse = 0; ///< Clock when build() last handed it out
  };
  /// By the program's whole source, as build() assembles its key.
  std::unordered_map<std::string, Entry> Programs;
  long Clock = 0; ///< build()s so far
  long Compiles = 0;
};

} // namespace bp

#endif
