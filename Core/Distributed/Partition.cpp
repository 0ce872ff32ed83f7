// SPDX-License-Identifier: BSD-3-Clause
#include "Partition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace bp
{

bool isEmptyBox(const Box& b)
{
  return b[0] > b[1] || b[2] > b[3] || b[4] > b[5];
}

Partition::Partition(std::vector<Box> pieces)
  : Pieces(std::move(pieces))
{
  const double inf = std::numeric_limits<double>::infinity();
  this->Bounds = { inf, -inf, inf, -inf, inf, -inf };
  for (const Box& b : this->Pieces)
  {
    if (isEmptyBox(b))
    {
      continue;
    }
    for (int a = 0; a < 3; ++a)
    {
      this->Bounds[2 * a] = std::min(this->Bounds[2 * a], b[2 * a]);
      this->Bounds[2 * a + 1] = std::max(this->Bounds[2 * a + 1], b[2 * a + 1]);
    }
  }
}

std::string Partition::validate(const std::vector<Box>& pieces)
{
  bool any = false;
  for (std::size_t k = 0; k < pieces.size(); ++k)
  {
    if (isEmptyBox(pieces[k]))
    {
      continue;
    }
    any = true;
    for (int a = 0; a < 3; ++a)
    {
      const double lo = pieces[k][2 * a], hi = pieces[k][2 * a + 1];
      if (!std::isfinite(lo) || !std::isfinite(hi))
      {
        std::ostringstream err;
        err << "piece " << k << " spans [" << lo << ", " << hi << "] along "
            << "XYZ"[a];
        return err.str();
      }
    }
  }
  return any ? std::string() : "no pieces";
}

int Partition::ownerOf(const float x[3]) const
{
  double q[3];
  for (int a = 0; a < 3; ++a)
  {
    const double v = std::isfinite(x[a]) ? double(x[a]) : this->Bounds[2 * a];
    q[a] = std::min(std::max(v, this->Bounds[2 * a]), this->Bounds[2 * a + 1]);
  }
  int nearest = -1;
  double nearestDistance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < this->pieceCount(); ++k)
  {
    const Box& b = this->Pieces[std::size_t(k)];
    if (isEmptyBox(b))
    {
      continue;
    }
    bool inside = true;
    double distance = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double lo = b[2 * a], hi = b[2 * a + 1];
      const bool upperFace = hi >= this->Bounds[2 * a + 1];
      inside = inside && q[a] >= lo && (q[a] < hi || upperFace);
      const double outside = std::max(std::max(lo - q[a], q[a] - hi), 0.0);
      distance += outside * outside;
    }
    if (inside)
    {
      return k;
    }
    // Boxes that tile the domain leave no gaps; rounding in the caller's
    // boxes might, and the nearest box closes them.
    if (distance < nearestDistance)
    {
      nearestDistance = distance;
      nearest = k;
    }
  }
  return nearest;
}

int ghostCellsNeeded(
  double elementSize, double maxSpeed, double dt, double cellLength, double reach)
{
  if (!(cellLength > 0.0) || !std::isfinite(cellLength))
  {
    return 2;
  }
  const double span = reach * std::abs(elementSize) + std::abs(maxSpeed * dt);
  const double cells = std::isfinite(span) ? std::ceil(span / cellLength) : 0.0;
  return int(std::min(cells, 1e6)) + 2;
}

void keepOwned(Engine& engine, const Partition& partition, int piece)
{
  std::vector<std::uint8_t> leaving(engine.elementCount(), 0);
  for (std::size_t e = 0; e < leaving.size(); ++e)
  {
    leaving[e] = partition.ownerOf(engine.centerOf(e).data()) != piece;
  }
  engine.exchange(leaving, {});
}

long long migrate(Engine& engine, const Partition& partition, int piece,
  const ExchangeFunction& exchange, std::string& error)
{
  const std::size_t held = engine.elementCount();
  std::vector<std::uint8_t> leaving(held, 0);
  std::vector<std::vector<std::uint32_t>> outgoing(std::size_t(partition.pieceCount()));
  long long left = 0;
  for (std::size_t e = 0; e < held; ++e)
  {
    const int owner = partition.ownerOf(engine.centerOf(e).data());
    if (owner != piece)
    {
      leaving[e] = 1;
      engine.packElement(e, outgoing[std::size_t(owner)]);
      ++left;
    }
  }
  const std::vector<std::uint32_t> incoming = exchange(outgoing);
  error = engine.exchange(leaving, incoming);
  return error.empty() ? left : -1;
}

} // namespace bp
