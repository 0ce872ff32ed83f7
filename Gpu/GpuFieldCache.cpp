// SPDX-License-Identifier: BSD-3-Clause
#include "GpuFieldCache.h"

#include "GpuPasses.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace bp
{
namespace
{
/// One rectilinear axis's bin lookup (bp_common.glsl).
struct AxisBins
{
  std::vector<float> cells; ///< per bin, the cell its start falls in
  int count = 1;
  float scale = 0.0f; ///< bins per unit of length
};

/// The bins of the axis whose coordinate table (value, spacing pairs) is
/// `table`: as many equal bins as make every bin at most half the narrowest
/// cell, so a bin spans at most two cells. Empty on success, otherwise why
/// the lookup would not fit in a texture `maxSize` texels wide.
std::string makeBins(const std::vector<float>& table, int axis, GLint maxSize, AxisBins& out)
{
  out = AxisBins();
  if (table.empty())
  {
    return std::string(); // uniform axis: no lookup
  }
  const std::size_t points = table.size() / 2;
  double narrowest = HUGE_VAL;
  for (std::size_t i = 0; i + 1 < points; ++i)
  {
    narrowest = std::min(narrowest, double(table[2 * i + 2]) - double(table[2 * i]));
  }
  const double span = double(table[2 * (points - 1)]) - double(table[0]);
  const double count = std::ceil(2.0 * span / narrowest) + 1.0;
  if (!(narrowest > 0.0) || count > double(maxSize))
  {
    std::ostringstream err;
    err << "the field's cells along axis "
        << "XYZ"[axis] << " range from " << narrowest << " to more than " << span / points
        << " in width; the GPU's lookup for them would need " << count
        << " texels, beyond its limit of " << maxSize << ". Use the CPU engine";
    return err.str();
  }
  out.count = int(count);
  out.scale = float(count / span);
  out.cells.resize(std::size_t(count));
  std::size_t cell = 0;
  for (std::size_t b = 0; b < out.cells.size(); ++b)
  {
    const float start = table[0] + float(double(b) * span / count);
    while (cell + 2 < points && table[2 * (cell + 1)] <= start)
    {
      ++cell;
    }
    out.cells[b] = float(cell);
  }
  return std::string();
}
} // namespace

std::string GpuFieldCache::checkSize(const GridGeometry& grid) const
{
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  for (int a = 0; a < 3; ++a)
  {
    if (grid.dims[a] > max3D)
    {
      std::ostringstream err;
      err << "the field's " << grid.dims[a] << " points along axis "
          << "XYZ"[a] << " exceed this GPU's GL_MAX_3D_TEXTURE_SIZE of " << max3D;
      return err.str();
    }
  }
  return std::string();
}

std::string GpuFieldCache::setField(const VectorField& field)
{
  const GridGeometry& grid = field.grid();
  std::string error = this->checkSize(grid);
  if (error.empty())
  {
    error = this->uploadAxes(field);
  }
  if (!error.empty())
  {
    return error;
  }
  this->Field.reset(new VectorField(field));
  this->fitSlots(grid);
  const FieldSlice* slices[2] = { &field.firstSlice(), &field.secondSlice() };
  int chosen[2] = { -1, -1 };
  for (int k = 0; k < 2; ++k)
  {
    if (!slices[k]->velocity)
    {
      continue;
    }
    // The first time step's slot stays out of reach of the second's eviction.
    Slot& slot = this->slotFor(slices[k]->velocity, chosen[0], -1);
    // Whatever has not arrived by slabs arrives now, at once.
    this->uploadLayers(slot, grid, std::max(grid.dims[2], 1));
    this->uploadOutside(slot, grid, *slices[k]);
    slot.lastUse = ++this->UseClock;
    chosen[k] = int(&slot - this->Slots.data());
  }
  this->CurrentSlots[0] = chosen[0];
  this->CurrentSlots[1] = chosen[1];
  return glGetError() == GL_NO_ERROR ? std::string()
                                     : std::string("the GPU could not hold the field's time steps");
}

int GpuFieldCache::stageSlice(const FieldSlice& slice, std::size_t maxBytes)
{
  if (!this->Field || !slice.velocity ||
    slice.velocity->size() != 3 * this->Field->grid().pointCount())
  {
    return 0;
  }
  const GridGeometry& grid = this->Field->grid();
  Slot& slot = this->slotFor(slice.velocity, this->CurrentSlots[0], this->CurrentSlots[1]);
  const std::size_t layerBytes = std::size_t(grid.dims[0]) * grid.dims[1] * 3 * sizeof(float);
  this->uploadLayers(slot, grid, int(std::max<std::size_t>(1, maxBytes / layerBytes)));
  this->uploadOutside(slot, grid, slice); // a twelfth of the velocities: at once
  return std::max(grid.dims[2], 1) - slot.layers;
}

int GpuFieldCache::residentTimeSteps() const
{
  int count = 0;
  for (const Slot& slot : this->Slots)
  {
    count += slot.data ? 1 : 0;
  }
  return count;
}

void GpuFieldCache::applyTo(GpuPass& pass) const
{
  const VectorField& field = *this->Field;
  const VectorField::SamplingConstants c = field.samplingConstants();
  pass.setVec3("bpOrigin", c.origin);
  pass.setVec3("bpInverseSpacing", c.inverseSpacing);
  pass.setVec3("bpMaxIndex", c.maxIndex);
  pass.setVec3("bpLower", c.lower);
  pass.setVec3("bpUpper", c.upper);
  // The corner past a cell's lower one along each axis; none on a flat axis.
  pass.setIVec3(
    "bpNextCorner", c.degenerate[0] ? 0 : 1, c.degenerate[1] ? 0 : 1, c.degenerate[2] ? 0 : 1);
  pass.setIVec3("bpDegenerate", c.degenerate[0], c.degenerate[1], c.degenerate[2]);
  pass.setIVec3("bpPeriodic", c.periodic[0], c.periodic[1], c.periodic[2]);
  pass.setIVec3("bpRectilinear", c.rectilinear[0], c.rectilinear[1], c.rectilinear[2]);
  const auto& dims = field.grid().dims;
  pass.setIVec3(
    "bpLastCell", std::max(dims[0] - 2, 0), std::max(dims[1] - 2, 0), std::max(dims[2] - 2, 0));
  pass.setIVec3("bpBins", this->Bins[0], this->Bins[1], this->Bins[2]);
  pass.setVec3("bpBinScale", this->BinScale);
  pass.setInt("bpUnsteady", field.isSteady() ? 0 : 1);
  // A steady field samples its one time step twice.
  const int second = field.isSteady() ? 0 : 1;
  pass.texture("bpField0", this->Slots[this->CurrentSlots[0]].texture.get(), GL_TEXTURE_3D);
  pass.texture("bpField1", this->Slots[this->CurrentSlots[second]].texture.get(), GL_TEXTURE_3D);
  pass.texture("bpAxes", this->AxesTexture.get());
  const Slot& first = this->Slots[this->CurrentSlots[0]];
  const Slot& next = this->Slots[this->CurrentSlots[second]];
  pass.setInt("bpMasked0", first.outside ? 1 : 0);
  pass.setInt("bpMasked1", next.outside ? 1 : 0);
  pass.texture("bpOutside0", this->outsideTextureOf(first), GL_TEXTURE_3D);
  pass.texture("bpOutside1", this->outsideTextureOf(next), GL_TEXTURE_3D);
}

void GpuFieldCache::applyReleaseMaskTo(GpuPass& pass, float minSpeed)
{
  const VectorField* field = this->Field.get();
  if (field && this->ReleaseFrom.changes(*field, minSpeed))
  {
    this->ReleaseUnfit = releaseUnfitCells(*field, minSpeed);
    const auto& dims = field->grid().dims;
    this->ReleaseTexture = this->ReleaseUnfit
      ? makeByteTexture3D(dims[0], dims[1], std::max(dims[2], 1), this->ReleaseUnfit->data())
      : GlTexture();
    this->WeightsFrom = nullptr; // the weights' reach depends on the mask
  }
  const bool masked = field && this->ReleaseTexture;
  pass.setInt("bpReleaseMasked", masked ? 1 : 0);
  pass.texture("bpReleaseUnfit", masked ? this->ReleaseTexture.get() : this->NoOutsideTexture.get(),
    GL_TEXTURE_3D);
  this->applyReleaseWeightsTo(pass);
}

void GpuFieldCache::applyReleaseWeightsTo(GpuPass& pass)
{
  const VectorField* field = this->Field.get();
  const auto& values = field ? field->firstSlice().releaseWeights : nullptr;
  if (values != this->WeightsFrom)
  {
    // Made once per time step's weights (ReleaseWeights.h).
    this->WeightsFrom = values;
    const auto weights =
      field ? releaseWeightsOf(field->grid(), values, this->ReleaseUnfit.get()) : nullptr;
    const auto& dims = field ? field->grid().dims : std::array<int, 3>{ 0, 0, 0 };
    this->WeightsTexture = weights
      ? makeFloatTexture3D(dims[0], dims[1], std::max(dims[2], 1), weights->triples().data())
      : GlTexture();
    this->WeightMax = weights ? weights->maximum() : 0.0f;
    this->WeightSupportMin = weights ? weights->supportMin() : std::array<float, 3>{};
    this->WeightSupportMax = weights ? weights->supportMax() : std::array<float, 3>{};
  }
  if (!this->NoWeightsTexture)
  {
    const float zero[3] = { 0, 0, 0 };
    this->NoWeightsTexture = makeFloatTexture3D(1, 1, 1, zero);
  }
  const bool weighted = field && this->WeightsTexture;
  pass.setInt("bpWeighted", weighted ? 1 : 0);
  pass.setFloat("bpWeightMax", this->WeightMax);
  pass.setVec3("bpWeightSupportMin", this->WeightSupportMin.data());
  pass.setVec3("bpWeightSupportMax", this->WeightSupportMax.data());
  pass.texture("bpReleaseWeights",
    weighted ? this->WeightsTexture.get() : this->NoWeightsTexture.get(), GL_TEXTURE_3D);
}

GLuint GpuFieldCache::outsideTextureOf(const Slot& slot) const
{
  return slot.outside ? slot.outsideTexture.get() : this->NoOutsideTexture.get();
}

void GpuFieldCache::uploadOutside(Slot& slot, const GridGeometry& grid, const FieldSlice& slice)
{
  if (!this->NoOutsideTexture)
  {
    const std::uint8_t inside = 0;
    this->NoOutsideTexture = makeByteTexture3D(1, 1, 1, &inside);
  }
  if (slot.outside == slice.outsideCells)
  {
    return;
  }
  slot.outside = slice.outsideCells;
  slot.outsideTexture = GlTexture();
  if (slot.outside && slot.outside->size() == grid.pointCount())
  {
    slot.outsideTexture = makeByteTexture3D(
      grid.dims[0], grid.dims[1], std::max(grid.dims[2], 1), slot.outside->data());
  }
  else
  {
    slot.outside = nullptr;
  }
}

GpuFieldCache::Slot& GpuFieldCache::slotFor(
  const std::shared_ptr<const std::vector<float>>& data, int keepA, int keepB)
{
  for (Slot& slot : this->Slots)
  {
    if (slot.data == data)
    {
      return slot;
    }
  }
  // An empty slot or the least recently used, other than the two kept.
  Slot* best = nullptr;
  for (int k = 0; k < int(this->Slots.size()); ++k)
  {
    Slot& slot = this->Slots[k];
    if (k != keepA && k != keepB && (!best || slot.lastUse < best->lastUse))
    {
      best = &slot;
    }
  }
  best->data = data;
  best->layers = 0;
  return *best;
}

void GpuFieldCache::uploadLayers(Slot& slot, const GridGeometry& grid, int count)
{
  const int nz = std::max(grid.dims[2], 1);
  if (!slot.texture)
  {
    GLuint name = 0;
    glGenTextures(1, &name);
    slot.texture = GlTexture(name);
    glBindTexture(GL_TEXTURE_3D, name);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage3D(
      GL_TEXTURE_3D, 0, GL_RGB32F, grid.dims[0], grid.dims[1], nz, 0, GL_RGB, GL_FLOAT, nullptr);
  }
  const int first = slot.layers, last = std::min(nz, slot.layers + std::max(count, 0));
  if (last <= first)
  {
    return;
  }
  glBindTexture(GL_TEXTURE_3D, slot.texture.get());
  TightUnpack unpack;
  const std::size_t layer = std::size_t(grid.dims[0]) * grid.dims[1] * 3;
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, first, grid.dims[0], grid.dims[1], last - first, GL_RGB,
    GL_FLOAT, slot.data->data() + layer * first);
  slot.layers = last;
}

void GpuFieldCache::fitSlots(const GridGeometry& grid)
{
  if (this->SlotDims == grid.dims)
  {
    return;
  }
  // A grid of another size: every resident time step goes (assigning an
  // empty slot deletes its texture).
  for (Slot& slot : this->Slots)
  {
    slot = Slot();
  }
  this->CurrentSlots[0] = this->CurrentSlots[1] = -1;
  this->SlotDims = grid.dims;
}

std::string GpuFieldCache::uploadAxes(const VectorField& field)
{
  std::array<std::vector<float>, 3> tables = { field.axisTable(0), field.axisTable(1),
    field.axisTable(2) };
  if (tables == this->AxesTables && this->AxesTexture)
  {
    return std::string();
  }
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  std::array<AxisBins, 3> bins;
  std::size_t width = 1;
  for (int a = 0; a < 3; ++a)
  {
    const std::string error = makeBins(tables[a], a, maxSize, bins[a]);
    this->Bins[a] = bins[a].count;
    this->BinScale[a] = bins[a].scale;
    if (!error.empty())
    {
      return error;
    }
    width = std::max({ width, tables[a].size() / 2, bins[a].cells.size() });
  }
  this->AxesTables = tables;
  // Rows 0-2: the axes' (value, spacing) tables; rows 3-5: their bin lookups.
  std::vector<float> texels(width * 6 * 2, 0.0f);
  for (int a = 0; a < 3; ++a)
  {
    std::copy(tables[a].begin(), tables[a].end(), texels.begin() + std::ptrdiff_t(a * width * 2));
    for (std::size_t b = 0; b < bins[a].cells.size(); ++b)
    {
      texels[((3 + a) * width + b) * 2] = bins[a].cells[b];
    }
  }
  if (!this->AxesTexture)
  {
    GLuint name = 0;
    glGenTextures(1, &name);
    this->AxesTexture = GlTexture(name);
  }
  glBindTexture(GL_TEXTURE_2D, this->AxesTexture.get());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  TightUnpack unpack;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, GLsizei(width), 6, 0, GL_RG, GL_FLOAT, texels.data());
  return std::string();
}

} // namespace bp
