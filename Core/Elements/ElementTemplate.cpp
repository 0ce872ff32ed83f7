// SPDX-License-Identifier: BSD-3-Clause
#include "ElementTemplate.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace bp
{
namespace
{
using Point = std::array<float, 3>;
using Tri = std::array<std::uint32_t, 3>;
using Pair = std::array<std::uint32_t, 2>;

float distance(const Point& p, const Point& q)
{
  const float dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// Unique undirected edges of the triangles, in first-seen order.
std::vector<Pair> triangleEdges(const std::vector<Tri>& triangles)
{
  std::vector<Pair> edges;
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const Tri& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (seen.insert({ std::min(a, b), std::max(a, b) }).second)
      {
        edges.push_back({ a, b });
      }
    }
  }
  return edges;
}

/// Flips triangles whose normal points towards `inside`.
void orientAwayFrom(const std::vector<Point>& p, std::vector<Tri>& triangles, const Point& inside)
{
  for (Tri& t : triangles)
  {
    const Point& a = p[t[0]];
    const Point& b = p[t[1]];
    const Point& c = p[t[2]];
    const float u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const float v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const float n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const float out[3] = { (a[0] + b[0] + c[0]) / 3 - inside[0],
      (a[1] + b[1] + c[1]) / 3 - inside[1], (a[2] + b[2] + c[2]) / 3 - inside[2] };
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0)
    {
      std::swap(t[1], t[2]);
    }
  }
}

ElementTemplate strip(const char* name, std::uint32_t columns)
{
  // Two rows of `columns` particles; particle 2i+r is column i, row r. Springs
  // hold each quad's edges and both diagonals (5m-4 springs: thesis Table 4.1's
  // 8(6)[16] and 16(14)[36]); the strip can still bend across its length.
  const float width = 0.6f;
  std::vector<Point> p;
  for (std::uint32_t i = 0; i < columns; ++i)
  {
    p.push_back({ float(i), 0.0f, 0.0f });
    p.push_back({ float(i), width, 0.0f });
  }
  std::vector<Tri> tris;
  std::vector<Pair> springs;
  for (std::uint32_t i = 0; i < columns; ++i)
  {
    springs.push_back({ 2 * i, 2 * i + 1 });
  }
  for (std::uint32_t i = 0; i + 1 < columns; ++i)
  {
    const std::uint32_t a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    tris.push_back({ a, c, d });
    tris.push_back({ a, d, b });
    springs.push_back({ a, c });
    springs.push_back({ b, d });
    springs.push_back({ a, d });
    springs.push_back({ b, c });
  }
  return makeTemplate(name, p, tris, springs);
}

ElementTemplate square()
{
  const std::vector<Point> p = { { -0.5f, -0.5f, 0 }, { 0.5f, -0.5f, 0 }, { 0.5f, 0.5f, 0 },
    { -0.5f, 0.5f, 0 } };
  return makeTemplate("Square", p, { { 0, 1, 2 }, { 0, 2, 3 } },
    { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 2 }, { 1, 3 } });
}

ElementTemplate cross()
{
  // A plus sign of 12 particles (the thesis padded it to 16). Beyond the drawn
  // edges, springs run across the full length between opposite arm tips and
  // between the tips of neighbouring arms, so the arms stay flat instead of
  // folding in (thesis §3.3).
  const std::vector<Point> p = {
    { -0.5f, -0.5f, 0 }, { 0.5f, -0.5f, 0 }, { 0.5f, 0.5f, 0 }, { -0.5f, 0.5f, 0 }, // centre
    { 1.5f, -0.5f, 0 }, { 1.5f, 0.5f, 0 },                                          // right arm
    { 0.5f, 1.5f, 0 }, { -0.5f, 1.5f, 0 },                                          // top arm
    { -1.5f, 0.5f, 0 }, { -1.5f, -0.5f, 0 },                                        // left arm
    { -0.5f, -1.5f, 0 }, { 0.5f, -1.5f, 0 },                                        // bottom arm
  };
  const std::vector<Tri> tris = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 4, 5 }, { 1, 5, 2 }, { 2, 6, 7 },
    { 2, 7, 3 }, { 3, 8, 9 }, { 3, 9, 0 }, { 0, 10, 11 }, { 0, 11, 1 } };
  std::vector<Pair> springs = triangleEdges(tris);
  const std::vector<Pair> extra = { { 4, 9 }, { 5, 8 }, { 6, 11 }, { 7, 10 }, // across
    { 5, 6 }, { 7, 8 }, { 9, 10 }, { 11, 4 } };                               // tip to tip
  springs.insert(springs.end(), extra.begin(), extra.end());
  return makeTemplate("Cross", p, tris, springs);
}

ElementTemplate paddlewheel()
{
  // The cube's eight corners (particle x + 2y + 4z) joined by all 28 springs,
  // drawn as the two diagonal planes through the z axis: four paddles.
  std::vector<Point> p;
  for (int i = 0; i < 8; ++i)
  {
    p.push_back({ (i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f });
  }
  std::vector<Pair> springs;
  for (std::uint32_t a = 0; a < 8; ++a)
  {
    for (std::uint32_t b = a + 1; b < 8; ++b)
    {
      springs.push_back({ a, b });
    }
  }
  const std::vector<Tri> tris = { { 0, 3, 7 }, { 0, 7, 4 }, { 1, 2, 6 }, { 1, 6, 5 } };
  return makeTemplate("Paddlewheel", p, tris, springs);
}

ElementTemplate tetrahedron()
{
  const std::vector<Point> p = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  std::vector<Tri> tris = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } };
  orientAwayFrom(p, tris, { 0, 0, 0 });
  return makeTemplate("Tetrahedron", p, tris, {});
}

ElementTemplate fish()
{
  // Tu and Terzopoulos (1994), "Artificial Fishes": 23 nodes and 91 springs.
  // Node 0 is the nose; nodes 1+4s..4+4s are the cross-section s (top, one
  // side, bottom, other side) at five stations along the body; nodes 21 and 22
  // are the upper and lower tips of the tail fin.
  const float station[5] = { 2.2f, 1.2f, 0.2f, -0.8f, -1.6f };
  const float halfHeight[5] = { 0.45f, 0.6f, 0.55f, 0.4f, 0.2f };
  const float halfWidth[5] = { 0.3f, 0.4f, 0.35f, 0.25f, 0.12f };
  std::vector<Point> p = { { 3.0f, 0, 0 } };
  for (int s = 0; s < 5; ++s)
  {
    p.push_back({ station[s], 0, halfHeight[s] });
    p.push_back({ station[s], halfWidth[s], 0 });
    p.push_back({ station[s], 0, -halfHeight[s] });
    p.push_back({ station[s], -halfWidth[s], 0 });
  }
  p.push_back({ -2.6f, 0, 0.7f });
  p.push_back({ -2.6f, 0, -0.7f });
  auto node = [](int s, int k) { return std::uint32_t(1 + 4 * s + (k & 3)); };

  std::vector<Pair> springs;
  std::vector<Tri> body;
  for (int k = 0; k < 4; ++k)
  {
    springs.push_back({ 0, node(0, k) });
    body.push_back({ 0, node(0, k), node(0, k + 1) });
  }
  for (int s = 0; s < 5; ++s)
  {
    for (int k = 0; k < 4; ++k)
    {
      springs.push_back({ node(s, k), node(s, k + 1) });
    }
    springs.push_back({ node(s, 0), node(s, 2) });
    springs.push_back({ node(s, 1), node(s, 3) });
  }
  for (int s = 0; s < 4; ++s)
  {
    for (int k = 0; k < 4; ++k)
    {
      springs.push_back({ node(s, k), node(s + 1, k) });
      springs.push_back({ node(s, k), node(s + 1, k + 1) });
      springs.push_back({ node(s, k + 1), node(s + 1, k) });
      body.push_back({ node(s, k), node(s + 1, k), node(s + 1, k + 1) });
      body.push_back({ node(s, k), node(s + 1, k + 1), node(s, k + 1) });
    }
  }
  for (int k = 0; k < 4; ++k)
  {
    springs.push_back({ 21, node(4, k) });
    springs.push_back({ 22, node(4, k) });
  }
  springs.push_back({ 21, 22 });
  body.push_back({ node(4, 0), node(4, 1), node(4, 2) });
  body.push_back({ node(4, 0), node(4, 2), node(4, 3) });
  // The body is star-shaped around a point on its axis.
  orientAwayFrom(p, body, { 0.4f, 0, 0 });
  // The tail fin is a flat quad in the x-z plane.
  std::vector<Tri> fin = { { node(4, 0), node(4, 2), 22 }, { node(4, 0), 22, 21 } };
  orientAwayFrom(p, fin, { -2.0f, -1.0f, 0 });
  body.insert(body.end(), fin.begin(), fin.end());
  return makeTemplate("Fish", p, body, springs);
}

} // namespace

std::string ElementTemplate::validate() const
{
  std::ostringstream err;
  const std::size_t n = this->rest.size();
  if (n == 0)
  {
    return "the element template has no particles";
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (float c : this->rest[i])
    {
      if (!std::isfinite(c))
      {
        err << "particle " << i << " of the element template has a non-finite rest position";
        return err.str();
      }
    }
  }
  if (this->springs.size() > MaxTemplateSprings)
  {
    err << "the element template has " << this->springs.size() << " springs, more than the "
        << MaxTemplateSprings << " a template may have";
    return err.str();
  }
  for (std::size_t s = 0; s < this->springs.size(); ++s)
  {
    const Spring& sp = this->springs[s];
    if (sp.a >= n || sp.b >= n)
    {
      err << "spring " << s << " joins particle " << std::max(sp.a, sp.b)
          << " but the element template has only " << n << " particles";
      return err.str();
    }
    if (sp.a == sp.b)
    {
      err << "spring " << s << " joins particle " << sp.a << " to itself";
      return err.str();
    }
    if (!(sp.stiffness >= 0.0f && sp.stiffness <= 1.0f))
    {
      err << "spring " << s << " has stiffness " << sp.stiffness << "; it must lie in [0, 1]";
      return err.str();
    }
    if (!std::isfinite(sp.restLength) || sp.restLength < 0.0f)
    {
      err << "spring " << s << " has an invalid rest length";
      return err.str();
    }
  }
  for (std::size_t t = 0; t < this->triangles.size(); ++t)
  {
    const auto& tri = this->triangles[t];
    if (tri[0] >= n || tri[1] >= n || tri[2] >= n)
    {
      err << "triangle " << t << " uses a particle index beyond the template's " << n
          << " particles";
      return err.str();
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      err << "triangle " << t << " repeats a particle";
      return err.str();
    }
  }
  if (!this->pinned.empty() && this->pinned.size() != n)
  {
    err << "the element template has " << this->pinned.size() << " pinned flags for " << n
        << " particles";
    return err.str();
  }
  return std::string();
}

void ElementTemplate::normalize()
{
  const std::size_t n = this->rest.size();
  if (n == 0)
  {
    return;
  }
  double c[3] = { 0, 0, 0 };
  for (const Point& p : this->rest)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[k];
    }
  }
  for (double& v : c)
  {
    v /= double(n);
  }
  double radius = 0.0;
  for (const Point& p : this->rest)
  {
    const double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
    radius = std::max(radius, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  const double scale = radius > 0.0 ? 0.5 / radius : 1.0;
  for (Point& p : this->rest)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = float((p[k] - c[k]) * scale);
    }
  }
  for (Spring& s : this->springs)
  {
    s.restLength = distance(this->rest[s.a], this->rest[s.b]);
  }
}

std::array<float, 3> longAxis(const ElementTemplate& shape)
{
  const std::size_t n = shape.particleCount();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& q : shape.rest)
  {
    mean += Eigen::Vector3d(q[0], q[1], q[2]) / double(std::max<std::size_t>(n, 1));
  }
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& q : shape.rest)
  {
    const Eigen::Vector3d d = Eigen::Vector3d(q[0], q[1], q[2]) - mean;
    spread += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(spread);
  const double largest = solver.eigenvalues()[2];
  // As long along x as along any direction (within rounding): x, exactly.
  if (!(largest > spread(0, 0) * (1.0 + 1e-6) + 1e-300) || !std::isfinite(largest))
  {
    return { 1.0f, 0.0f, 0.0f };
  }
  Eigen::Vector3d axis = solver.eigenvectors().col(2).normalized();
  int biggest = 0;
  for (int a = 1; a < 3; ++a)
  {
    biggest = std::abs(axis[a]) > std::abs(axis[biggest]) ? a : biggest;
  }
  axis *= axis[biggest] < 0.0 ? -1.0 : 1.0; // one sign, whatever the solver's
  return { float(axis[0]), float(axis[1]), float(axis[2]) };
}

ElementTemplate builtinTemplate(BuiltinShape shape)
{
  switch (shape)
  {
    case BuiltinShape::Point:
      return makeTemplate("Point", { { 0, 0, 0 } }, {}, {});
    case BuiltinShape::Square:
      return square();
    case BuiltinShape::Strip4:
      return strip("Strip4", 2);
    case BuiltinShape::Strip8:
      return strip("Strip8", 4);
    case BuiltinShape::Strip16:
      return strip("Strip16", 8);
    case BuiltinShape::Cross:
      return cross();
    case BuiltinShape::Paddlewheel:
      return paddlewheel();
    case BuiltinShape::Tetrahedron:
      return tetrahedron();
    case BuiltinShape::Fish:
      return fish();
  }
  return makeTemplate("Point", { { 0, 0, 0 } }, {}, {});
}

std::vector<int> colourSprings(std::size_t particles, const std::vector<Spring>& springs)
{
  std::vector<std::vector<int>> used(particles); // colours touching each particle
  std::vector<int> colour(springs.size(), 0);
  for (std::size_t k = 0; k < springs.size(); ++k)
  {
    const auto& a = used[springs[k].a];
    const auto& b = used[springs[k].b];
    int c = 0;
    while (
      std::find(a.begin(), a.end(), c) != a.end() || std::find(b.begin(), b.end(), c) != b.end())
    {
      ++c;
    }
    colour[k] = c;
    used[springs[k].a].push_back(c);
    used[springs[k].b].push_back(c);
  }
  return colour;
}

std::vector<Pair> meshSprings(
  std::size_t particles, const std::vector<Tri>& triangles, MeshSprings mode)
{
  if (mode == MeshSprings::AllPairs)
  {
    std::vector<Pair> all;
    for (std::uint32_t a = 0; a < particles; ++a)
    {
      for (std::uint32_t b = a + 1; b < particles; ++b)
      {
        all.push_back({ a, b });
      }
    }
    return all;
  }
  std::vector<Pair> springs = triangleEdges(triangles);
  if (mode == MeshSprings::EdgesAndDiagonals)
  {
    // For each edge, the corners opposite it in the triangles that share it.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> opposite;
    for (const Tri& t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
        opposite[{ std::min(a, b), std::max(a, b) }].push_back(c);
      }
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const Pair& e : springs)
    {
      seen.insert({ std::min(e[0], e[1]), std::max(e[0], e[1]) });
    }
    for (const auto& edge : opposite)
    {
      const auto& corners = edge.second;
      for (std::size_t i = 0; i < corners.size(); ++i)
      {
        for (std::size_t j = i + 1; j < corners.size(); ++j)
        {
          const std::uint32_t a = std::min(corners[i], corners[j]);
          const std::uint32_t b = std::max(corners[i], corners[j]);
          if (a != b && seen.insert({ a, b }).second)
          {
            springs.push_back({ a, b });
          }
        }
      }
    }
  }
  return springs;
}

std::vector<std::uint32_t> triangleStrip(const ElementTemplate& shape)
{
  const auto& triangles = shape.triangles;
  if (triangles.size() < 2 || triangles.size() > MaxStripTriangles)
  {
    return {};
  }
  // Each triangle by its directed edges (a -> b in its counter-clockwise order).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> byEdge;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int q = 0; q < 3; ++q)
    {
      byEdge[{ triangles[t][q], triangles[t][(q + 1) % 3] }] = t;
    }
  }
  for (std::size_t first = 0; first < triangles.size(); ++first)
  {
    for (int q = 0; q < 3; ++q)
    {
      const auto& t0 = triangles[first];
      std::vector<std::uint32_t> s = { t0[q], t0[(q + 1) % 3], t0[(q + 2) % 3] };
      std::vector<bool> used(triangles.size(), false);
      used[first] = true;
      for (std::size_t k = 1; k < triangles.size(); ++k)
      {
        // Strip triangle k starts with this directed edge.
        const auto edge = k % 2 ? std::make_pair(s[k + 1], s[k]) : std::make_pair(s[k], s[k + 1]);
        const auto found = byEdge.find(edge);
        if (found == byEdge.end() || used[found->second])
        {
          break;
        }
        used[found->second] = true;
        const auto& t = triangles[found->second];
        std::vector<std::uint32_t> third;
        for (int r = 0; r < 3; ++r)
        {
          if (t[r] != edge.first && t[r] != edge.second)
          {
            third.push_back(t[r]);
          }
        }
        if (third.size() != 1)
        {
          break; // a degenerate triangle
        }
        s.push_back(third[0]);
      }
      if (s.size() == triangles.size() + 2)
      {
        return s;
      }
    }
  }
  return {};
}

ElementTemplate makeTemplate(const std::string& name, const std::vector<Point>& points,
  const std::vector<Tri>& triangles, const std::vector<Pair>& springPairs)
{
  ElementTemplate t;
  t.name = name;
  t.rest = points;
  t.triangles = triangles;
  const std::vector<Pair> pairs = springPairs.empty() ? triangleEdges(triangles) : springPairs;
  for (const Pair& pr : pairs)
  {
    Spring s;
    s.a = pr[0];
    s.b = pr[1];
    t.springs.push_back(s);
  }
  // Rest lengths need valid indices; an invalid template keeps zero lengths and
  // is reported by validate().
  bool indicesValid = true;
  for (const Spring& s : t.springs)
  {
    indicesValid = indicesValid && s.a < points.size() && s.b < points.size();
  }
  if (indicesValid)
  {
    t.normalize();
  }
  return t;
}

} // namespace bp
