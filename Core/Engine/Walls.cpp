// SPDX-License-Identifier: BSD-3-Clause
#include "Walls.h"

namespace bp
{

bool onWall(const Domain& box, const float p[3])
{
  for (int a = 0; a < 3; ++a)
  {
    if (box.bounded(a) && (p[a] == box.lower[a] || p[a] == box.upper[a]))
    {
      return true;
    }
  }
  return false;
}

WallHits clampToBox(const Domain& box, float p[3])
{
  WallHits hits = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (!box.bounded(a))
    {
      continue;
    }
    if (p[a] < box.lower[a])
    {
      p[a] = box.lower[a];
      hits |= 1u << (2 * a);
    }
    else if (p[a] > box.upper[a])
    {
      p[a] = box.upper[a];
      hits |= 1u << (2 * a + 1);
    }
  }
  return hits;
}

namespace
{
/// Stick: the first point of before -> p on a side, for `before` in the box.
WallHits stickAlongStep(const Domain& box, const float before[3], float p[3])
{
  // The fraction of the step at which each side crossed is met; the
  // smallest wins. Only axes p crossed count, and there p != before.
  float first = 1.0f;
  int axis = -1;
  float wall = 0.0f;
  for (int a = 0; a < 3; ++a)
  {
    if (!box.bounded(a))
    {
      continue;
    }
    const float w = p[a] < box.lower[a] ? box.lower[a] : p[a] > box.upper[a] ? box.upper[a] : p[a];
    if (w == p[a])
    {
      continue;
    }
    const float t = (w - before[a]) / (p[a] - before[a]);
    if (axis < 0 || t < first)
    {
      first = t;
      axis = a;
      wall = w;
    }
  }
  if (axis < 0)
  {
    return 0;
  }
  for (int a = 0; a < 3; ++a)
  {
    p[a] = a == axis ? wall : before[a] + first * (p[a] - before[a]);
  }
  // Rounding may leave another coordinate a hair beyond its side.
  const WallHits hit = 1u << (2 * axis + (wall == box.upper[axis] ? 1 : 0));
  return hit | clampToBox(box, p);
}
} // namespace

WallHits wallAfterAdvection(
  Boundary b, float restitution, const Domain& box, const float before[3], float p[3])
{
  switch (b)
  {
    case Boundary::Stick:
      return box.contains(before) ? stickAlongStep(box, before, p) : clampToBox(box, p);
    case Boundary::Slip:
      return clampToBox(box, p);
    case Boundary::Bounce:
    {
      WallHits hits = 0;
      for (int a = 0; a < 3; ++a)
      {
        if (!box.bounded(a))
        {
          continue;
        }
        if (p[a] < box.lower[a])
        {
          p[a] = box.lower[a] + restitution * (box.lower[a] - p[a]);
          hits |= 1u << (2 * a);
        }
        else if (p[a] > box.upper[a])
        {
          p[a] = box.upper[a] - restitution * (p[a] - box.upper[a]);
          hits |= 1u << (2 * a + 1);
        }
      }
      return hits | clampToBox(box, p);
    }
    default:
      return 0;
  }
}

void wallVelocity(Boundary b, float restitution, WallHits hits, float v[3])
{
  if (!hits)
  {
    return;
  }
  if (b == Boundary::Stick)
  {
    v[0] = v[1] = v[2] = 0.0f;
    return;
  }
  for (int a = 0; a < 3; ++a)
  {
    const bool lower = hits & (1u << (2 * a));
    const bool upper = hits & (1u << (2 * a + 1));
    if ((lower && v[a] < 0.0f) || (upper && v[a] > 0.0f))
    {
      v[a] = b == Boundary::Bounce ? -restitution * v[a] : 0.0f;
    }
  }
}

} // namespace bp
