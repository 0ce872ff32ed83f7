// SPDX-License-Identifier: BSD-3-Clause
#include "GpuTemplate.h"

#include "Engine.h"
#include "ParticleLayout.h"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <vector>

namespace bp
{
namespace
{
/// The template's tables on the host, texel by texel (4 floats each).
struct TemplateTables
{
  std::vector<float> rest;      ///< per particle
  std::vector<float> info;      ///< per particle: springs row, then triangles row
  std::vector<float> springs;   ///< per particle, its springs in index order: 2 texels each
  std::vector<float> triangles; ///< per particle, its triangles in index order
};

/// The shares of a spring's correction its ends a and b take: a pinned end
/// none, so its other end takes it all (Engine.h).
std::array<float, 2> springShares(const Spring& s, const std::vector<std::uint8_t>& pinned)
{
  const bool pa = pinned[s.a] != 0, pb = pinned[s.b] != 0;
  return { pa ? 0.0f : (pb ? 1.0f : 0.5f), pb ? 0.0f : (pa ? 1.0f : 0.5f) };
}

/// One spring's two texels as its end `end` (0: a, 1: b) sees it; `listed`
/// marks an entry of the coloured table (an empty texel there means none).
std::array<float, 8> springEntry(
  const Spring& s, const std::array<float, 2>& shares, int end, float elementSize, float listed)
{
  return { float(s.a), float(s.b), end == 0 ? shares[0] : -shares[1], listed,
    s.restLength * elementSize, s.stiffness, 0.0f, 0.0f };
}

TemplateTables makeTables(
  const ElementTemplate& shape, const std::vector<std::uint8_t>& pinned, float elementSize)
{
  const int n = int(shape.particleCount());
  TemplateTables t;
  t.info.assign(std::size_t(n) * 2 * 4, 0.0f);
  std::vector<int> degree(n, 0);
  for (const Spring& s : shape.springs)
  {
    ++degree[s.a];
    ++degree[s.b];
  }
  // Each particle's springs and triangles in index order, bucketed in one
  // pass over each (a pass per particle over all of them took minutes on a
  // mesh of 200,000 points).
  std::vector<std::vector<std::uint32_t>> springsOf(n), trianglesOf(n);
  for (std::size_t k = 0; k < shape.springs.size(); ++k)
  {
    springsOf[shape.springs[k].a].push_back(std::uint32_t(k));
    springsOf[shape.springs[k].b].push_back(std::uint32_t(k));
  }
  for (std::size_t k = 0; k < shape.triangles.size(); ++k)
  {
    const auto& tri = shape.triangles[k];
    for (int c = 0; c < 3; ++c)
    {
      // A degenerate triangle lists a corner twice: the particle takes it once.
      if (c == 0 || (tri[c] != tri[0] && (c == 1 || tri[c] != tri[1])))
        trianglesOf[tri[c]].push_back(std::uint32_t(k));
    }
  }
  for (int i = 0; i < n; ++i)
  {
    const std::uint32_t index = std::uint32_t(i);
    t.rest.insert(t.rest.end(), { shape.rest[i][0], shape.rest[i][1], shape.rest[i][2], 0.0f });
    float* springsRow = &t.info[4 * i];
    springsRow[0] = float(t.springs.size() / 8);
    for (std::uint32_t k : springsOf[i])
    {
      const Spring& s = shape.springs[k];
      const std::array<float, 8> entry =
        springEntry(s, springShares(s, pinned), s.a == index ? 0 : 1, elementSize, 0.0f);
      t.springs.insert(t.springs.end(), entry.begin(), entry.end());
    }
    springsRow[1] = float(t.springs.size() / 8) - springsRow[0];
    springsRow[2] = degree[i] > 0 ? 1.0f / float(degree[i]) : 0.0f;
    springsRow[3] = pinned[i] ? 1.0f : 0.0f;
    float* trianglesRow = &t.info[4 * (n + i)];
    trianglesRow[0] = float(t.triangles.size() / 4);
    for (std::uint32_t k : trianglesOf[i])
    {
      const auto& tri = shape.triangles[k];
      t.triangles.insert(t.triangles.end(), { float(tri[0]), float(tri[1]), float(tri[2]), 0.0f });
    }
    trianglesRow[1] = float(t.triangles.size() / 4) - trianglesRow[0];
  }
  return t;
}

/// bpSpringSum() of bp_restore.glsl with the springs as code: one case per
/// particle, its springs' corrections in list order (so the same bits as the
/// buffer), constants written to float precision.
std::string writeSpringSum(const TemplateTables& t, int n)
{
  std::ostringstream code;
  code << "vec3 bpSpringSum(int e, int i, vec4 info)\n{\n  vec3 acc = vec3(0.0);\n"
       << "  switch (i)\n  {\n";
  code.precision(9);
  code << std::scientific;
  for (int i = 0; i < n; ++i)
  {
    const int first = int(t.info[4 * i]), count = int(t.info[4 * i + 1]);
    if (count == 0)
      continue;
    code << "    case " << i << ":\n";
    for (int k = first; k < first + count; ++k)
    {
      const float* e = &t.springs[8 * std::size_t(k)];
      code << "      acc += bpSpringCorrection(e, " << int(e[0]) << ", " << int(e[1]) << ", "
           << e[2] << ", " << e[4] << ", " << e[5] << ");\n";
    }
    code << "      break;\n";
  }
  code << "  }\n  return acc;\n}\n";
  return code.str();
}

/// Per (colour, particle) the particle's spring of that colour, two texels,
/// for the Gauss-Seidel pass; `colours` is how many there are.
std::vector<float> colouredSpringTable(const ElementTemplate& shape,
  const std::vector<std::uint8_t>& pinned, float elementSize, int& colours)
{
  const std::size_t n = shape.particleCount();
  const std::vector<int> colour = colourSprings(n, shape.springs);
  colours = colour.empty() ? 0 : *std::max_element(colour.begin(), colour.end()) + 1;
  std::vector<float> texels(2 * n * std::size_t(std::max(colours, 1)) * 4, 0.0f);
  for (std::size_t k = 0; k < shape.springs.size(); ++k)
  {
    const Spring& s = shape.springs[k];
    const std::array<float, 2> shares = springShares(s, pinned);
    const std::uint32_t ends[2] = { s.a, s.b };
    for (int end = 0; end < 2; ++end)
    {
      const std::array<float, 8> entry = springEntry(s, shares, end, elementSize, 1.0f);
      std::copy(
        entry.begin(), entry.end(), &texels[4 * (std::size_t(colour[k]) * 2 * n + 2 * ends[end])]);
    }
  }
  return texels;
}

/// Texels a row of a list of `count` texels: at least `least`, at most
/// ListTextureWidth (as gpuTextureError counts the rows).
int listWidth(std::size_t count, std::size_t least)
{
  return int(
    std::min<std::size_t>(std::max<std::size_t>(count, least), std::size_t(ListTextureWidth)));
}
} // namespace

void GpuTemplate::upload(const ElementTemplate& shape, float elementSize, bool writeSpringCode)
{
  const int n = int(shape.particleCount());
  const std::vector<std::uint8_t> pinned =
    shape.pinned.empty() ? std::vector<std::uint8_t>(std::size_t(n), 0) : shape.pinned;
  const TemplateTables tables = makeTables(shape, pinned, elementSize);
  this->springSumCode = writeSpringCode ? writeSpringSum(tables, n) : std::string();
  const std::vector<float> coloured =
    colouredSpringTable(shape, pinned, elementSize, this->colourCount);
  this->restMomentInverse = bp::restMomentInverse(shape, elementSize);

  TightUnpack unpack;
  this->colouredSprings = makeTexture2D(2 * n, std::max(this->colourCount, 1), coloured.data());
  this->rest = makeTexture2D(n, 1, tables.rest.data());
  this->particleInfo = makeTexture2D(n, 2, tables.info.data());
  this->springsWidth = listWidth(tables.springs.size() / 4, 2);
  this->springsWidth += this->springsWidth % 2;
  this->springs = makeListTexture(tables.springs, this->springsWidth);
  this->trianglesWidth = listWidth(tables.triangles.size() / 4, 1);
  this->triangles = makeListTexture(tables.triangles, this->trianglesWidth);
}

} // namespace bp
