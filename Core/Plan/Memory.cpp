// SPDX-License-Identifier: BSD-3-Clause
#include "Memory.h"

#include "Inertia.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__) && __has_include(<malloc.h>)
#include <malloc.h>
#define BOUNDPARTICLES_HAS_MALLOC_TRIM 1
#endif

namespace bp
{
namespace
{
/// The bytes the process maps now (its virtual size), or 0 if unknown.
double mappedBytes()
{
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f)
  {
    return 0.0;
  }
  unsigned long pages = 0;
  const int read = std::fscanf(f, "%lu", &pages);
  std::fclose(f);
  return read == 1 ? double(pages) * double(sysconf(_SC_PAGESIZE)) : 0.0;
}

std::string gigabytes(double bytes)
{
  std::ostringstream out;
  out.precision(3);
  out << bytes / double(1 << 30) << " GiB";
  return out.str();
}
} // namespace

double allocatableBytes()
{
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  double limit = physical > 0.0 ? physical : 1e300;
  struct rlimit address;
  if (getrlimit(RLIMIT_AS, &address) == 0 && address.rlim_cur != RLIM_INFINITY)
  {
    limit = std::min(limit, double(address.rlim_cur) - mappedBytes());
  }
  return std::max(limit, 0.0);
}

double traceBytes(const ElementTemplate& shape, const Parameters& p)
{
  const double n = double(shape.particleCount()), elements = double(p.numberOfElements);
  // Per particle: the engine's positions and forces (16 bytes; it keeps no
  // normals for the output), twice (the copy a short step is shown on); the
  // output's points (up to 24), normals, velocity (12 each), six float
  // arrays, ElementId (8) and ParticleIndex (4).
  // Heavy particles (Inertia.h) keep a slip velocity more: 12 bytes.
  const double engine = 16 + (carriesInertia(p) ? 12 : 0);
  const double perParticle = 2 * engine + 24 + 12 + 12 + 6 * 4 + 8 + 4;
  // Per element: lifetimes, generations, centres, orientations, flags and
  // visiting order, twice; and its cells (a vtkIdType per corner plus offsets).
  const double corners = !shape.triangles.empty() ? 3.0 * double(shape.triangles.size())
    : !shape.springs.empty()                      ? 2.0 * double(shape.springs.size())
                                                  : n;
  const double cells = !shape.triangles.empty() ? double(shape.triangles.size())
    : !shape.springs.empty()                    ? double(shape.springs.size())
                                                : n;
  // Poses and spins (32 bytes), twice, and their output (8 floats a particle).
  const double perElement = 2 * 48 + 2 * 32 + 8 * (corners + cells);
  // A trail: per pose, the positions and generation (twice: the shown copy),
  // and in the output its points with a copy of every array, and its cells.
  const double trail = std::max(p.trailLength, 0) *
    (2 * (12 * n + 4) + n * (perParticle - 2 * engine + 4) + 8 * (corners + cells));
  return elements * (n * (perParticle + 8 * 4) + perElement + trail);
}

std::string checkAllocatable(double bytes, const std::string& what)
{
  const double available = allocatableBytes();
  if (bytes <= available)
  {
    return std::string();
  }
  return what + " needs about " + gigabytes(bytes) + ", more than the " + gigabytes(available) +
    " this process can allocate";
}

void returnFreedMemory()
{
#ifdef BOUNDPARTICLES_HAS_MALLOC_TRIM
  malloc_trim(0);
#endif
}

} // namespace bp
