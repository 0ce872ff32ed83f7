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

VectorField FieldCache::field(const GridGeometry& grid, const std::vector<int>& ids) const
{
  if (ids.size() == 1)
  {
    return VectorField(grid, this->at(ids[0]));
  }
  return VectorField(grid, this->at(ids[0]), this->at(ids[1]));
}

} // namespace bp
