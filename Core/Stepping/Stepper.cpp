// SPDX-License-Identifier: BSD-3-Clause
#include "Stepper.h"

#include <algorithm>
#include <utility>

namespace bp
{

CpuStepper::CpuStepper(RangeRunner run)
  : Run(std::move(run))
{
}

std::string CpuStepper::configure(const ElementTemplate& shape, const Parameters& parameters)
{
  return this->Current.configure(shape, parameters);
}

std::string CpuStepper::setField(const VectorField& field)
{
  // A field is a grid and shared time steps: copying it copies no velocities.
  this->Field = std::make_shared<const VectorField>(field);
  const float speed = this->Current.parameters().releaseMinSpeed;
  if (this->ReleaseFrom.changes(field, speed))
  {
    this->Release = this->releaseMaskOf(field, speed);
  }
  this->Current.setReleaseMask(this->Release.grid, this->Release.unfit, this->Release.weights);
  return std::string();
}

ReleaseMask CpuStepper::releaseMaskOf(const VectorField& field, float minSpeed)
{
  return bp::releaseMaskOf(field, minSpeed);
}

void CpuStepper::initialize(double startTime)
{
  this->Current.initialize(this->Run, startTime, this->Field.get());
}

void CpuStepper::step(double t, double h)
{
  this->Current.step(*this->Field, t, h, this->Run);
}

void CpuStepper::save()
{
  // Assignment copies the state, not the step's scratch (Engine::StepScratch),
  // and reuses the copy's storage from the last save.
  this->Saved = this->Current;
}

void CpuStepper::restore()
{
  // The scratch goes with the swap: the engine sizes it again where it is used.
  std::swap(this->Current, this->Saved);
}

void CpuStepper::setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max)
{
  // The copy too: a short step shown and taken back must not bring the old box back.
  this->Current.setEmitter(min, max);
  this->Saved.setEmitter(min, max);
}

void CpuStepper::keepCheckpoint(long long steps, double time)
{
  // A copy as save() makes: the state, not the step's scratch; the emitter
  // box is part of it (in situ, where it changes, keeps no checkpoints).
  this->Copies[steps] = this->Current;
  this->Checkpoints.add(steps, time);
}

void CpuStepper::resumeCheckpoint(long long steps)
{
  const auto copy = this->Copies.find(steps);
  if (copy == this->Copies.end())
  {
    return; // the plan resumes only from a copy it was told of
  }
  this->Current = copy->second;
  this->cursor.steps = steps;
  this->cursor.committed = this->Checkpoints.timeOf(steps);
  this->cursor.showsPartialStep = false;
}

void CpuStepper::dropCheckpoints()
{
  this->Copies.clear();
  Stepper::dropCheckpoints();
}

double CpuStepper::checkpointBytes() const
{
  return 4.0 * double(this->Current.recordWords()) *
    double(std::max<std::size_t>(this->Current.parameters().numberOfElements, 1));
}

bool CpuStepper::committedState(EngineState& state)
{
  // While a short step is shown, the committed boundary is save()'s copy.
  state = (this->cursor.showsPartialStep ? this->Saved : this->Current).saveState();
  return true;
}

std::string CpuStepper::loadState(const EngineState& state)
{
  return this->Current.loadState(state);
}

const Engine* CpuStepper::particles()
{
  return &this->Current;
}

DistributedStepper::DistributedStepper(
  RangeRunner run, ExchangeFunction exchange, ReleaseMaskFunction releaseMask)
  : CpuStepper(std::move(run))
  , Exchange(std::move(exchange))
  , WholeReleaseMask(std::move(releaseMask))
{
}

ReleaseMask DistributedStepper::releaseMaskOf(const VectorField& piece, float minSpeed)
{
  // Releases land anywhere in the whole field: every piece must agree.
  return this->WholeReleaseMask ? this->WholeReleaseMask(piece, minSpeed) : ReleaseMask();
}

void DistributedStepper::setPieces(const Partition& partition, const Domain& domain, int piece)
{
  this->Pieces.reset(new Partition(partition));
  this->WholeDomain = domain;
  this->Piece = piece;
}

void DistributedStepper::initialize(double startTime)
{
  this->CpuStepper::initialize(startTime);
  // The reposition test takes the whole field's domain, not the ghosted piece's.
  this->engine().setDomain(this->WholeDomain);
  keepOwned(this->engine(), *this->Pieces, this->Piece);
}

std::string DistributedStepper::loadState(const EngineState& state)
{
  if (!this->Pieces)
  {
    return "the pieces of the distributed run are not set";
  }
  const std::string error = this->CpuStepper::loadState(state);
  if (!error.empty())
  {
    return error;
  }
  // As initialize() does: the whole field's domain, and this piece's elements.
  this->engine().setDomain(this->WholeDomain);
  keepOwned(this->engine(), *this->Pieces, this->Piece);
  return std::string();
}

void DistributedStepper::step(double t, double h)
{
  // Resets first, so that an element reset into another piece moves there
  // before it samples the field; then the exchange; then the step proper,
  // which has nothing left to reset.
  Engine& engine = this->engine();
  engine.resetDue(this->runner(), t, h);
  std::string error;
  const long long left = migrate(engine, *this->Pieces, this->Piece, this->Exchange, error);
  this->Migrated += std::max(left, 0LL);
  if (!error.empty())
  {
    this->Error = error;
  }
  this->CpuStepper::step(t, h);
}

long long DistributedStepper::takeMigrated()
{
  const long long count = this->Migrated;
  this->Migrated = 0;
  return count;
}

std::string DistributedStepper::takeExchangeError()
{
  std::string error;
  error.swap(this->Error);
  return error;
}

} // namespace bp
