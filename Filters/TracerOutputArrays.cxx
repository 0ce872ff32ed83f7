// SPDX-License-Identifier: BSD-3-Clause
#include "TracerOutputArrays.h"

#include "ElementStretch.h"

#include "ElementNormals.h"
#include "SampleAtPositions.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace bpvtk
{
namespace
{
float* floats(vtkDataArray* a)
{
  return static_cast<vtkFloatArray*>(a)->GetPointer(0);
}

/// Each particle's slip (0 without inertia) at `out`, 3 floats a particle.
void copySlips(const bp::Engine& engine, std::size_t begin, std::size_t end, float* out)
{
  const std::vector<float>& slips = engine.slips();
  if (slips.empty())
  {
    std::fill(out + 3 * begin, out + 3 * end, 0.0f);
    return;
  }
  std::copy(slips.data() + 3 * begin, slips.data() + 3 * end, out + 3 * begin);
}

/// Normals (of whole elements: the block's ends are whole elements), Force
/// and SlipVelocity.
void writeParticleState(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  const std::size_t n = c.engine.particlesPerElement();
  switch (row.id)
  {
    case bp::OutputArrayId::Normals:
      // From the positions, straight into the output: the engine's own
      // normals would cost a pass and a copy more (issue 16).
      bp::elementsNormals(c.engine.shape(), c.engine.positions().data() + 3 * begin,
        floats(out) + 3 * begin, (end - begin) / n);
      break;
    case bp::OutputArrayId::Force:
      std::copy(
        c.engine.forces().data() + begin, c.engine.forces().data() + end, floats(out) + begin);
      break;
    case bp::OutputArrayId::SlipVelocity:
      copySlips(c.engine, begin, end, floats(out));
      break;
    default:
      break;
  }
}

/// The field's velocity at particles [begin, end) into `velocity` (3 floats
/// each, from its first), and |curl| into `vorticity` (may be null).
void sampleParticles(
  const FillContext& c, std::size_t begin, std::size_t end, float* velocity, float* vorticity)
{
  bp::sampleAtPositions(c.field, c.frame.time, c.engine.positions().data() + 3 * begin, end - begin,
    velocity, vorticity, c.serial);
  for (std::size_t k = 0; c.frame.backward && velocity && k < 3 * (end - begin); ++k)
  {
    velocity[k] = -velocity[k];
  }
}

/**
 * Velocity, and Vorticity from the same cell, in one pass: the Velocity row
 * writes both (the table lists it first), and the Vorticity row only when
 * Velocity is left out.
 */
void writeFieldSample(const bp::OutputArray& row, vtkDataArray* /*out*/, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  vtkDataArray* velocityArray = c.array(bp::OutputArrayId::Velocity);
  vtkDataArray* vorticityArray = c.array(bp::OutputArrayId::Vorticity);
  if (row.id == bp::OutputArrayId::Vorticity && velocityArray)
  {
    return; // written with Velocity
  }
  float* vorticity = vorticityArray ? floats(vorticityArray) + begin : nullptr;
  if (velocityArray)
  {
    sampleParticles(c, begin, end, floats(velocityArray) + 3 * begin, vorticity);
  }
  else
  {
    std::vector<float> velocity(3 * (end - begin));
    sampleParticles(c, begin, end, velocity.data(), vorticity);
  }
}

/// Speed: |Velocity|, and ParticleVelocity: Velocity plus the slip, from
/// the Velocity array where the output has it.
void writeDerived(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  if (row.id != bp::OutputArrayId::Speed && row.id != bp::OutputArrayId::ParticleVelocity)
  {
    return;
  }
  std::vector<float> sampled; // Velocity's values when the output leaves it out
  const float* v;
  if (vtkDataArray* velocity = c.array(bp::OutputArrayId::Velocity))
  {
    v = floats(velocity) + 3 * begin;
  }
  else
  {
    sampled.resize(3 * (end - begin));
    sampleParticles(c, begin, end, sampled.data(), nullptr);
    v = sampled.data();
  }
  if (row.id == bp::OutputArrayId::ParticleVelocity)
  {
    float* particle = floats(out);
    copySlips(c.engine, begin, end, particle);
    for (std::size_t i = 0; i < 3 * (end - begin); ++i)
    {
      particle[3 * begin + i] += v[i];
    }
    return;
  }
  float* speed = floats(out) + begin;
  for (std::size_t i = 0; i < end - begin; ++i)
  {
    const float* w = v + 3 * i;
    speed[i] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
}

/// Writes value(e) on particles [begin, end), e being each one's element.
template <typename T, typename Value>
void perElement(T* out, std::size_t n, std::size_t begin, std::size_t end, const Value& value)
{
  for (std::size_t e = begin / n; e < end / n; ++e)
  {
    std::fill_n(out + e * n, n, T(value(e)));
  }
}

/// Writes `count` floats of each element's tuple of `stride` at `values` on
/// particles [begin, end).
void perElementTuple(float* out, std::size_t n, std::size_t begin, std::size_t end,
  const float* values, std::size_t stride, std::size_t count)
{
  for (std::size_t i = begin; i < end; ++i)
  {
    std::copy_n(values + (i / n) * stride, count, out + i * count);
  }
}

/// ElementStretch (2 components) or ElementFTLE of the elements of
/// particles [begin, end): one fit of each element against its template.
void writeDeformation(
  bool stretch, float* out, const bp::Engine& engine, std::size_t begin, std::size_t end)
{
  const std::size_t n = engine.particlesPerElement();
  const bp::StretchFit fit(engine.shape().rest, engine.parameters().elementSize);
  for (std::size_t e = begin / n; e < end / n; ++e)
  {
    const double age = double(engine.drawnLifetime(e)) - double(engine.lifetimes()[e]);
    const std::array<float, 3> d =
      bp::elementDeformation(fit, engine.positions().data() + 3 * e * n, age,
        engine.resetFlags()[e] & bp::HiddenFlags, engine.parameters().ftleMinimumAge);
    for (std::size_t i = e * n; i < (e + 1) * n; ++i)
    {
      if (stretch)
      {
        out[2 * i] = d[0];
        out[2 * i + 1] = d[1];
      }
      else
      {
        out[i] = d[2];
      }
    }
  }
}

void writeElementState(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  const bp::Engine& engine = c.engine;
  const std::size_t n = engine.particlesPerElement();
  const int axis = c.frame.coloringAxis;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const std::array<double, 2> centre = bp::radialCenter(c.frame.domain, axis);
  const double cu = centre[0], cv = centre[1];
  const float* centres = engine.initialCenters().data();
  switch (row.id)
  {
    case bp::OutputArrayId::Lifetime:
      // An element whose life ended in the last step is released at the next:
      // none left, not a negative time.
      perElement(floats(out), n, begin, end,
        [&](std::size_t e) { return std::max(engine.lifetimes()[e], 0.0f); });
      break;
    case bp::OutputArrayId::ElementId:
      perElement(static_cast<vtkIdTypeArray*>(out)->GetPointer(0), n, begin, end,
        [&](std::size_t e) { return engine.elementIds()[e]; });
      break;
    case bp::OutputArrayId::Layer: // the release centre along the colouring axis
      perElement(floats(out), n, begin, end,
        [&](std::size_t e) { return double(centres[3 * e + axis]) + c.frame.offset[axis]; });
      break;
    case bp::OutputArrayId::Radius: // the release centre's distance from the axis
      perElement(floats(out), n, begin, end,
        [&](std::size_t e)
        { return std::hypot(centres[3 * e + u] - cu, centres[3 * e + v] - cv); });
      break;
    case bp::OutputArrayId::ElementOrientation:
      perElementTuple(floats(out), n, begin, end, engine.poses().data(), 4, 4);
      break;
    case bp::OutputArrayId::ElementSpin:
      perElementTuple(floats(out), n, begin, end, engine.spins().data(), 4, 3);
      for (std::size_t k = 3 * begin; c.frame.backward && k < 3 * end; ++k)
      {
        floats(out)[k] = -floats(out)[k]; // the turn per time of the data, as Velocity
      }
      break;
    case bp::OutputArrayId::SpinVorticityRatio:
      perElementTuple(floats(out), n, begin, end, engine.spins().data() + 3, 4, 1);
      break;
    case bp::OutputArrayId::ElementStretch:
    case bp::OutputArrayId::ElementFTLE:
      writeDeformation(
        row.id == bp::OutputArrayId::ElementStretch, floats(out), engine, begin, end);
      break;
    default:
      break;
  }
}

void writeTemplateIndex(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  if (row.id == bp::OutputArrayId::ParticleIndex)
  {
    int* index = static_cast<vtkIntArray*>(out)->GetPointer(0);
    const std::size_t n = c.engine.particlesPerElement();
    for (std::size_t e = begin / n; e < end / n; ++e)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        index[e * n + i] = int(i);
      }
    }
  }
}

/// FNV-1a over 64-bit words.
class Key
{
public:
  Key& add(std::uint64_t word)
  {
    this->Value = (this->Value ^ word) * 1099511628211ull;
    return *this;
  }
  Key& add(double value)
  {
    std::uint64_t word;
    std::memcpy(&word, &value, sizeof(word));
    return this->add(word);
  }
  template <typename T>
  Key& add(const std::vector<T>& values)
  {
    const std::size_t bytes = values.size() * sizeof(T);
    const auto* p = reinterpret_cast<const unsigned char*>(values.data());
    this->add(std::uint64_t(bytes));
    std::size_t k = 0;
    for (; k + 8 <= bytes; k += 8)
    {
      std::uint64_t word;
      std::memcpy(&word, p + k, 8);
      this->add(word);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, p + k, bytes - k);
    return this->add(tail);
  }
  std::uint64_t value() const { return this->Value | 1; } // never 0

private:
  std::uint64_t Value = 1469598103934665603ull;
};
} // namespace

std::uint64_t unchangedKey(const bp::OutputArray& row, const FillContext& c)
{
  if (!c.trail.empty())
  {
    return 0;
  }
  Key key;
  key.add(std::uint64_t(row.id)).add(std::uint64_t(c.engine.particlesPerElement()));
  switch (row.id)
  {
    case bp::OutputArrayId::ParticleIndex:
      return key.add(std::uint64_t(c.engine.elementCount())).value();
    case bp::OutputArrayId::ElementId:
      return key.add(c.engine.elementIds()).value();
    case bp::OutputArrayId::Layer:
    case bp::OutputArrayId::Radius:
      // The release centres, in the frame they are measured in.
      key.add(c.engine.initialCenters()).add(std::uint64_t(c.frame.coloringAxis));
      for (int a = 0; a < 3; ++a)
      {
        key.add(c.frame.offset[a]).add(c.frame.domain[2 * a]).add(c.frame.domain[2 * a + 1]);
      }
      return key.value();
    default:
      return 0;
  }
}

std::vector<TrailPose> trailPoses(
  const bp::Engine& engine, const bp::VectorField& field, double time)
{
  std::vector<TrailPose> poses;
  const int length = int(engine.trailTimes().size());
  const std::size_t E = engine.elementCount();
  const auto& periodic = field.grid().periodic;
  const bool seams = periodic[0] || periodic[1] || periodic[2];
  for (int k = 0; k < length; ++k)
  {
    const std::size_t slot = std::size_t(engine.trailSlot(k));
    const double recorded = engine.trailTimes()[slot];
    if (!(recorded < time))
    {
      continue;
    }
    for (std::size_t e = 0; e < E; ++e)
    {
      // A pose from before the element's move across a periodic seam would
      // lie a period away: the trail breaks there.
      if (engine.trailGenerations()[slot * E + e] == engine.generations()[e] &&
        !(engine.resetFlags()[e] & bp::HiddenFlags) &&
        !(seams && engine.trailAcrossSeam(slot, e, field)))
      {
        poses.push_back({ slot, e, float(time - recorded) });
      }
    }
  }
  return poses;
}

void writeParticles(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end)
{
  switch (row.source)
  {
    case bp::ArraySource::ParticleState:
      writeParticleState(row, out, c, begin, end);
      break;
    case bp::ArraySource::FieldSample:
      writeFieldSample(row, out, c, begin, end);
      break;
    case bp::ArraySource::Derived:
      writeDerived(row, out, c, begin, end);
      break;
    case bp::ArraySource::ElementState:
      writeElementState(row, out, c, begin, end);
      break;
    case bp::ArraySource::TemplateIndex:
      writeTemplateIndex(row, out, c, begin, end);
      break;
    case bp::ArraySource::TrailAge: // 0 on the elements themselves
      std::fill(floats(out) + begin, floats(out) + end, 0.0f);
      break;
  }
}

void extendToTrail(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c)
{
  const std::size_t N = c.engine.particleCount(), n = c.engine.particlesPerElement();
  const std::size_t E = c.engine.elementCount();
  if (row.source == bp::ArraySource::TrailAge)
  {
    for (std::size_t j = 0; j < c.trail.size(); ++j)
    {
      std::fill_n(floats(out) + N + j * n, n, c.trail[j].age);
    }
    return;
  }
  if (row.id == bp::OutputArrayId::Normals)
  {
    float* normals = floats(out);
    for (std::size_t j = 0; j < c.trail.size(); ++j)
    {
      const TrailPose& t = c.trail[j];
      bp::elementNormals(c.engine.shape(),
        c.engine.trailPositions().data() + 3 * (t.slot * E + t.element) * n,
        normals + 3 * (N + j * n));
    }
    return;
  }
  auto* bytes = static_cast<unsigned char*>(out->GetVoidPointer(0));
  const std::size_t tuple = std::size_t(out->GetDataTypeSize() * out->GetNumberOfComponents());
  for (std::size_t j = 0; j < c.trail.size(); ++j)
  {
    std::memcpy(bytes + (N + j * n) * tuple, bytes + c.trail[j].element * n * tuple, n * tuple);
  }
}

} // namespace bpvtk
