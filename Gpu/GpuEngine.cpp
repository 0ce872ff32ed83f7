// SPDX-License-Identifier: BSD-3-Clause
#include "GpuEngine.h"

#include "GpuEngineState.h"
#include "GpuSystem.h"
#include "VectorField.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <utility>

namespace bp
{

/// The caller's settings and the system. release() assigns an empty system
/// over the old one, which deletes every GL object it holds (GlObjects.h);
/// the settings outlive it.
struct GpuEngine::Internals
{
  int textureSizeLimit = 1 << 30;
  bool generatedSprings = false;
  FusedSteps fusedSteps = FusedSteps::Automatic;
  PassObserver* observer = nullptr; ///< set again on every new system
  /// The programs of every configure since the last release(): a
  /// configure with settings seen before compiles nothing again.
  GpuProgramCache programs;
  GpuSystem system;
};

GpuEngine::GpuEngine()
  : I(new Internals)
{
}

// Calls no GL (the context may not be current): GL objects are deleted by
// release() only, and those still held are left to their context (GlObjects.h).
GpuEngine::~GpuEngine() = default;

int GpuEngine::particleTextureWidth() const
{
  return this->I->system.layout.particleTextureWidth;
}

int GpuEngine::particleTextureHeight() const
{
  return this->I->system.layout.particleTextureHeight;
}

void GpuEngine::release()
{
  this->I->system = GpuSystem(); // deletes every GL object the old one held
  this->I->programs.clear();
}

void GpuEngine::setGeneratedSprings(bool generated)
{
  this->I->generatedSprings = generated;
}

bool GpuEngine::generatedSprings() const
{
  return this->I->generatedSprings;
}

void GpuEngine::setFusedSteps(FusedSteps choice)
{
  this->I->fusedSteps = choice;
}

GpuPath GpuEngine::path() const
{
  return this->I->system.passes.path();
}

bool GpuEngine::fusedStep() const
{
  return bool(this->I->system.passes.programs.step);
}

long GpuEngine::uniformLookups() const
{
  return this->I->system.passes.uniformLookups();
}

long GpuEngine::programsCompiled() const
{
  return this->I->programs.compiles();
}

std::size_t GpuEngine::programsKept() const
{
  return this->I->programs.size();
}

void GpuEngine::setPassObserver(PassObserver* observer)
{
  this->I->observer = observer;
  this->I->system.passes.setObserver(observer);
}

void GpuEngine::setTextureSizeLimit(int texels)
{
  this->I->textureSizeLimit = texels;
}

std::string GpuEngine::configure(const ElementTemplate& shape, const Parameters& p)
{
  // The same checks as the CPU engine, then the GPU's own limits.
  std::string error = Engine::validate(shape, p);
  if (!error.empty())
  {
    // As for any configure that fails: nothing of the old system, nor a
    // cached program, outlives it (a display releases only what it configured).
    this->release();
    return error;
  }
  Internals& I = *this->I;
  I.system = GpuSystem(); // deletes the old system's GL objects; its programs stay cached
  I.programs.beginUse();
  error = I.system.make(shape, p, I.textureSizeLimit, I.generatedSprings, I.fusedSteps, I.programs);
  if (!error.empty())
  {
    // No GL object outlives a configure that fails, its programs neither: a
    // display releases the engine only once it has configured it.
    this->release();
  }
  I.system.passes.setObserver(I.observer);
  return error;
}

std::string GpuEngine::setField(const VectorField& field)
{
  return this->I->system.fieldCache.setField(field);
}

void GpuEngine::setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max)
{
  // Every pass sets its uniforms from the parameters (GpuPasses::begin).
  this->I->system.parameters.emitterMin = min;
  this->I->system.parameters.emitterMax = max;
}

int GpuEngine::stageSlice(const FieldSlice& slice, std::size_t maxBytes)
{
  return this->I->system.fieldCache.stageSlice(slice, maxBytes);
}

int GpuEngine::stageSliceWithin(const FieldSlice& slice, double seconds)
{
  const auto start = std::chrono::steady_clock::now();
  int remaining;
  do
  {
    remaining = this->stageSlice(slice, std::size_t(1) << 20);
  } while (remaining > 0 &&
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds);
  return remaining;
}

int GpuEngine::residentTimeSteps() const
{
  return this->I->system.fieldCache.residentTimeSteps();
}

void GpuEngine::initialize(double startTime)
{
  this->I->system.initialize(startTime);
}

void GpuEngine::step(double t, double h)
{
  this->I->system.step(t, h);
}

void GpuEngine::updateNormals()
{
  this->I->system.updateNormals();
}

void GpuEngine::saveState()
{
  this->I->system.state.save(this->I->system.passes, this->I->system.layout);
}

void GpuEngine::restoreState()
{
  this->I->system.state.restore(this->I->system.passes, this->I->system.layout);
}

std::string GpuEngine::readState(EngineState& state, bool saved) const
{
  return readEngineState(this->I->system, saved, state);
}

std::string GpuEngine::loadState(const EngineState& state)
{
  return loadEngineState(this->I->system, state);
}

void GpuEngine::keepCheckpoint(long long steps)
{
  this->I->system.state.keepCheckpoint(this->I->system.passes, this->I->system.layout, steps);
}

bool GpuEngine::resumeCheckpoint(long long steps)
{
  return this->I->system.state.resumeCheckpoint(
    this->I->system.passes, this->I->system.layout, steps);
}

void GpuEngine::dropCheckpoints()
{
  this->I->system.state.dropCheckpoints();
}

int GpuEngine::checkpointCount() const
{
  return int(this->I->system.state.checkpointCount());
}

double GpuEngine::checkpointBytes() const
{
  return this->I->system.state.checkpointBytes(this->I->system.layout);
}

void GpuEngine::updateFieldSamples(double t)
{
  this->I->system.updateFieldSamples(t);
}

void GpuEngine::readFieldSamples(std::vector<float>* velocity, std::vector<float>* vorticity) const
{
  this->I->system.passes.readParticles(
    this->I->system.state.samples.get(), this->I->system.layout, velocity, vorticity);
}

GpuEngine::DrawInputs GpuEngine::drawInputs() const
{
  const GpuSystem& S = this->I->system;
  DrawInputs d;
  using E = ElementTexture;
  d.positions = S.state.particles.current();
  d.normals = S.state.normals.get();
  d.samples = S.state.samples.get();
  d.elements = S.state.current(E::State);
  d.centers = S.state.current(E::Centers);
  d.poses = S.state.current(E::Poses);
  d.spins = S.state.current(E::Spins);
  d.slips = carriesInertia(S.parameters) ? S.state.slips.get() : 0u;
  d.elementGrid[0] = S.layout.elementGrid[0];
  d.elementGrid[1] = S.layout.elementGrid[1];
  d.blocksPerRow = S.layout.blocksPerRow;
  d.elementCount = S.layout.elementCount;
  d.particlesPerElement = S.layout.particlesPerElement;
  const TrailRing& trail = S.state.trail;
  d.trailLength = trail.length();
  for (int k = 0; k < trail.length(); ++k)
  {
    const std::size_t slot = std::size_t(trail.slot(k));
    d.trail.push_back({ trail.particles[slot], trail.elements[slot], trail.times[slot] });
  }
  if (const VectorField* field = S.fieldCache.field())
  {
    const std::array<float, 3> half = field->domain().halfPeriods();
    std::copy(half.begin(), half.end(), d.trailHalfPeriods);
  }
  return d;
}

void GpuEngine::readPoses(std::vector<float>* poses, std::vector<float>* spins) const
{
  const GpuSystem& S = this->I->system;
  const std::size_t values = 4 * std::size_t(S.layout.elementCount);
  std::vector<float> texels;
  const std::pair<GLuint, std::vector<float>*> reads[] = {
    { S.state.current(ElementTexture::Poses), poses },
    { S.state.current(ElementTexture::Spins), spins }
  };
  for (const auto& read : reads)
  {
    if (read.second)
    {
      // Element e is texel e in row-major order.
      S.passes.readTexture(read.first, S.layout.elementGrid[0], S.layout.elementGrid[1], texels);
      read.second->assign(texels.begin(), texels.begin() + std::ptrdiff_t(values));
    }
  }
}

int GpuEngine::trailLength() const
{
  return this->I->system.state.trail.length();
}

double GpuEngine::trailTime(int k) const
{
  const TrailRing& trail = this->I->system.state.trail;
  return trail.times[std::size_t(trail.slot(k))];
}

void GpuEngine::readTrail(
  int k, std::vector<float>* positions, std::vector<std::uint32_t>* generations) const
{
  const GpuSystem& S = this->I->system;
  const std::size_t slot = std::size_t(S.state.trail.slot(k));
  if (positions)
  {
    S.passes.readParticles(S.state.trail.particles[slot], S.layout, positions, nullptr);
  }
  if (generations)
  {
    std::vector<float> texels;
    S.passes.readTexture(
      S.state.trail.elements[slot], S.layout.elementGrid[0], S.layout.elementGrid[1], texels);
    generations->resize(std::size_t(S.layout.elementCount));
    for (std::size_t e = 0; e < generations->size(); ++e)
    {
      const float g = texels[4 * e + 1];
      (*generations)[e] = g < 0.0f ? NoTrailPose : std::uint32_t(g);
    }
  }
}

void GpuEngine::read(
  std::vector<float>* positions, std::vector<float>* forces, std::vector<float>* normals) const
{
  const GpuSystem& S = this->I->system;
  if (positions || forces)
  {
    S.passes.readParticles(S.state.particles.current(), S.layout, positions, forces);
  }
  if (normals)
  {
    S.passes.readParticles(S.state.normals.get(), S.layout, normals, nullptr);
  }
}

void GpuEngine::readSlips(std::vector<float>& slips) const
{
  const GpuSystem& S = this->I->system;
  slips.clear();
  if (carriesInertia(S.parameters))
  {
    S.passes.readParticles(S.state.slips.get(), S.layout, &slips, nullptr);
  }
}

void GpuEngine::readElements(std::vector<float>* lifetimes, std::vector<float>* generations,
  std::vector<float>* centers, std::vector<float>* orientations, std::vector<float>* resetFlags,
  std::vector<float>* hidden) const
{
  const GpuSystem& S = this->I->system;
  const int elements = S.layout.elementCount;
  std::vector<float> texels;
  const auto readPerElement = [&](GLuint texture)
  { S.passes.readTexture(texture, S.layout.elementGrid[0], S.layout.elementGrid[1], texels); };
  if (orientations)
  {
    readPerElement(S.state.current(ElementTexture::Orientations));
    orientations->assign(texels.begin(), texels.begin() + 4 * std::size_t(elements));
  }
  // Per element: lifetime, generation, reset flag (the fourth: non-finite).
  readPerElement(S.state.current(ElementTexture::State));
  std::vector<float>* columns[3] = { lifetimes, generations, resetFlags };
  for (int c = 0; c < 3; ++c)
  {
    if (!columns[c])
      continue;
    columns[c]->resize(std::size_t(elements));
    for (int e = 0; e < elements; ++e)
      (*columns[c])[e] = texels[4 * e + c];
  }
  if (centers || hidden)
  {
    // Per element: the release centre, and whether it is hidden.
    readPerElement(S.state.current(ElementTexture::Centers));
    for (int e = 0; centers && e < elements; ++e)
    {
      centers->resize(std::size_t(elements) * 3);
      std::copy(&texels[4 * e], &texels[4 * e] + 3, centers->begin() + 3 * e);
    }
    for (int e = 0; hidden && e < elements; ++e)
    {
      hidden->resize(std::size_t(elements));
      (*hidden)[e] = texels[4 * e + 3];
    }
  }
}

} // namespace bp
