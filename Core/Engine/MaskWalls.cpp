// SPDX-License-Identifier: BSD-3-Clause
#include "MaskWalls.h"

#include <algorithm>
#include <cmath>

namespace bp
{

bool firstOutsideFace(
  const VectorField& field, float weight, const float from[3], const float to[3], MaskFace& face)
{
  const Domain& box = field.domain();
  for (int a = 0; a < 3; ++a)
  {
    // Across a periodic side the cells' indices wrap and the faces'
    // coordinates do not: no face is found there.
    if (box.periodic[a] &&
      !(from[a] >= box.lower[a] && from[a] <= box.upper[a] && to[a] >= box.lower[a] &&
        to[a] <= box.upper[a]))
    {
      return false;
    }
  }
  int cell[3], end[3];
  field.cellOf(from, cell);
  field.cellOf(to, end);
  if (field.outsideCellIndexed(cell, weight))
  {
    return false;
  }
  for (int k = 0; k < MaxMaskWallCrossings; ++k)
  {
    int axis = -1, step = 0;
    float first = 0.0f, plane = 0.0f;
    for (int a = 0; a < 3; ++a)
    {
      if (cell[a] == end[a])
      {
        continue;
      }
      const int s = end[a] > cell[a] ? 1 : -1;
      const float w = field.pointCoordinate(a, s > 0 ? cell[a] + 1 : cell[a]);
      const float d = to[a] - from[a];
      const float t = d != 0.0f ? std::min(std::max((w - from[a]) / d, 0.0f), 1.0f) : 0.0f;
      if (axis < 0 || t < first)
      {
        axis = a;
        step = s;
        first = t;
        plane = w;
      }
    }
    if (axis < 0)
    {
      return false;
    }
    std::copy_n(cell, 3, face.cell);
    cell[axis] += step;
    if (field.outsideCellIndexed(cell, weight))
    {
      face.axis = axis;
      face.plane = plane;
      face.toward = float(-step);
      for (int a = 0; a < 3; ++a)
      {
        face.point[a] = a == axis ? plane : from[a] + first * (to[a] - from[a]);
      }
      return true;
    }
  }
  return false;
}

WallHits wallOnOutsideCells(Boundary b, float restitution, float offset, const VectorField& field,
  float weight, const float before[3], float p[3], MaskFace& first)
{
  if (!field.outsideCellAt(p, weight))
  {
    return 0;
  }
  float from[3], last[3];
  std::copy_n(before, 3, from);
  std::copy_n(before, 3, last);
  WallHits hits = 0;
  for (int k = 0; k < MaxMaskWallRules; ++k)
  {
    MaskFace face;
    if (!firstOutsideFace(field, weight, from, p, face))
    {
      std::copy_n(last, 3, p); // before the step where no face was met yet
      return hits ? hits : WallMaskedCell;
    }
    if (k == 0)
    {
      first = face;
    }
    const int a = face.axis;
    const float inside = face.plane + offset * face.toward;
    std::copy_n(face.point, 3, last);
    last[a] = inside;
    for (int j = 0; j < 3; ++j)
    {
      if (j != a && field.domain().bounded(j))
      {
        const float lo = field.pointCoordinate(j, face.cell[j]) + offset;
        const float hi = field.pointCoordinate(j, face.cell[j] + 1) - offset;
        last[j] = std::min(std::max(last[j], lo), hi);
      }
    }
    hits |= 1u << (2 * a + (face.toward < 0.0f ? 1 : 0));
    if (b == Boundary::Stick)
    {
      std::copy_n(last, 3, p);
      return hits;
    }
    const float beyond = std::fabs(p[a] - face.plane);
    p[a] = b == Boundary::Bounce ? face.plane + face.toward * std::max(restitution * beyond, offset)
                                 : inside;
    if (!field.outsideCellAt(p, weight))
    {
      return hits;
    }
    std::copy_n(last, 3, from);
  }
  std::copy_n(last, 3, p);
  return hits;
}

bool onOutsideFace(const VectorField& field, float weight, float offset, const float p[3])
{
  if (!field.hasOutsideCells() || !std::isfinite(p[0] + p[1] + p[2]))
  {
    return false;
  }
  int cell[3];
  field.cellOf(p, cell);
  if (field.outsideCellIndexed(cell, weight))
  {
    return false;
  }
  const Domain& box = field.domain();
  for (int a = 0; a < 3; ++a)
  {
    if (box.degenerate[a])
    {
      continue;
    }
    int next[3] = { cell[0], cell[1], cell[2] };
    next[a] = cell[a] - 1;
    const float below = p[a] - field.pointCoordinate(a, cell[a]);
    if (cell[a] > 0 && below >= 0.0f && below <= 2.0f * offset &&
      field.outsideCellIndexed(next, weight))
    {
      return true;
    }
    next[a] = cell[a] + 1;
    const float above = field.pointCoordinate(a, cell[a] + 1) - p[a];
    if (cell[a] < field.lastCellOf(a) && above >= 0.0f && above <= 2.0f * offset &&
      field.outsideCellIndexed(next, weight))
    {
      return true;
    }
  }
  return false;
}

} // namespace bp
