// SPDX-License-Identifier: BSD-3-Clause
#include "FieldCache.h"

#include <algorithm>

namespace bp
{

int FieldCache::firstMissing(const std::vector<int>& indices) const
{
  for (int i : indices)
  {
    if (!this->has(i))
    {
      return i;
    }
  }
  return -1;
}

void FieldCache::insert(int index, const FieldSlice& slice, const std::vector<int>& keep)
{
  if (this->Slices.size() >= Capacity && !this->has(index))
  {
    for (auto it = this->Slices.begin(); it != this->Slices.end();)
    {
      const bool kept = std::find(keep.begin(), keep.end(), it->first) != keep.end();
      it = kept ? std::next(it) : this->Slices.erase(it);
    }
  }
  this->Slices[index] = slice;
}

void FieldCache::dropBefore(int index)
{
  this->Slices.erase(this->Slices.begin(), this->Slices.lower_bound(index));
}

std::size_t FieldCache::regrid(
  const GridGeometry& from, const GridGeometry& to, const FieldSlice& present)
{
  std::size_t outside = 0;
  for (auto& held : this->Slices)
  {
    outside = 0; // every held step is on `from`: each counts the same points
    held.second = regridSlice(from, held.second, to, present, outside);
  }
  return outside;
}

FieldSlice regridSlice(const GridGeometry& from, const FieldSlice& slice, const GridGeometry& to,
  const FieldSlice& present, std::size_t& outside)
{
  const VectorField old(from, slice);
  const std::vector<float>& now = *present.velocity;
  auto velocity = std::make_shared<std::vector<float>>(3 * to.pointCount());
  std::vector<float>& v = *velocity;
  outside = 0;
  std::size_t n = 0;
  for (int k = 0; k < std::max(to.dims[2], 1); ++k)
  {
    for (int j = 0; j < std::max(to.dims[1], 1); ++j)
    {
      for (int i = 0; i < std::max(to.dims[0], 1); ++i, n += 3)
      {
        const float p[3] = { float(to.coordinate(0, i)), float(to.coordinate(1, j)),
          float(to.coordinate(2, k)) };
        if (old.contains(p))
        {
          old.sampleWeighted(p, 0.0f, &v[n]);
        }
        else
        {
          std::copy(now.begin() + std::ptrdiff_t(n), now.begin() + std::ptrdiff_t(n + 3), &v[n]);
          ++outside;
        }
      }
    }
  }
  FieldSlice regridded = present;
  regridded.time = slice.time;
  regridded.velocity = velocity;
  return regridded;
}

VectorField FieldCache::field(const GridGeometry& grid, const std::vector<int>& ids) const
{
  if (ids.size() == 1)
  {
    return VectorField(grid, this->at(ids[0]));
  }
  return VectorField(grid, this->at(ids[0]), this->at(ids[1]));
}

} // namespace bp
