// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Stepper.h
 * @brief One interface for everything that steps a system of bound particles.
 *
 * The tracer drives a trace through these verbs only: configure the system,
 * set the field, place every element, step, save / restore the state
 * around a short step shown between two step boundaries, and keep or resume
 * checkpoints (Checkpoints.h) of the whole state on step boundaries. Three kinds of
 * stepper implement them:
 *  - CpuStepper: the CPU engine in this process;
 *  - DistributedStepper: a CpuStepper on a piece of a distributed run
 *    (Partition.h), whose step also hands elements to the pieces that now
 *    own them;
 *  - WorkQueue (WorkQueue.h): records the calls for a renderer that runs the
 *    GPU engine in its own GL context (Gpu/GpuStepper.h replays them there).
 * So the tracer holds one stepper and never asks which it is.
 */
#ifndef BoundParticles_Stepper_h
#define BoundParticles_Stepper_h

#include "Checkpoints.h"
#include "DomainMask.h"
#include "ElementTemplate.h"
#include "Engine.h"
#include "Parallel.h"
#include "Partition.h"
#include "VectorField.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace bp
{

/**
 * Where a stepper stands once all its work is done: what the trace plan
 * (TracePlan.h) decides replay-or-continue from.
 */
struct TraceCursor
{
  bool valid = false;              ///< holds a trace at all
  double committed = 0.0;          ///< the last step boundary reached
  long long steps = 0;             ///< steps from the start to `committed`
  std::uint64_t configuration = 0; ///< the tracer configuration it was made for
  std::uint64_t producer = 0;      ///< which tracer made it
  bool showsPartialStep = false;   ///< a short step past `committed` is shown (restore() first)
};

class Stepper
{
public:
  virtual ~Stepper() = default;

  /// Checks the template and parameters and sizes the system; empty on success.
  virtual std::string configure(const ElementTemplate& shape, const Parameters& parameters) = 0;
  /// The field later steps sample; empty on success.
  virtual std::string setField(const VectorField& field) = 0;
  /// Places every element (generation 0) at `startTime` (the release window's test).
  virtual void initialize(double startTime) = 0;
  /// One step of size h from time t on the field last set.
  virtual void step(double t, double h) = 0;
  /// Keeps a copy of the state, so a short step can be shown and taken back.
  virtual void save() = 0;
  /// Goes back to the copy save() kept.
  virtual void restore() = 0;
  /// From now on releases draw from the box [min, max] (engine coordinates)
  /// instead of the configured emitter box: in situ, after the grid changed
  /// (bp::emitterInChangedField). Kept by save() and restore() alike.
  virtual void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max) = 0;

  /// @name Checkpoints (Checkpoints.h): copies of the whole state on step
  /// boundaries, which going back resumes from instead of replaying.
  ///@{
  /// Whether this stepper keeps checkpoints at all.
  virtual bool keepsCheckpoints() const { return false; }
  /// Keeps a copy of the state as it stands: on the boundary `time`, `steps`
  /// steps from the start.
  virtual void keepCheckpoint(long long /*steps*/, double /*time*/) {}
  /// Goes back to the copy kept after `steps` steps (checkpoints().has(steps));
  /// the cursor stands there, with no short step shown.
  virtual void resumeCheckpoint(long long /*steps*/) {}
  /// Drops every copy (a replay from the start, or the trace's end).
  virtual void dropCheckpoints() { this->Checkpoints.clear(); }
  /// The copies held: their step counts and times.
  const CheckpointIndex& checkpoints() const { return this->Checkpoints; }
  /// The bytes one copy of the whole system takes, as configured (every
  /// process of a distributed run alike), for the spacing
  /// (bp::checkpointSpacing); 0 before a configure.
  virtual double checkpointBytes() const { return 0.0; }
  ///@}

  /// @name A state to save and resume (EngineState.h)
  ///@{
  /// The engine's state at the committed boundary (the copy save() kept
  /// while a short step is shown); false where it cannot be had (a
  /// renderer's GPU textures that no display reads back: WorkQueue::readState).
  virtual bool committedState(EngineState& /*state*/) { return false; }
  /// After configure(), setField() and initialize(): replaces the elements
  /// by the state's (a piece of a distributed run keeps those whose centres
  /// lie in it); empty on success, otherwise why not.
  virtual std::string loadState(const EngineState& /*state*/)
  {
    return "this engine cannot resume a saved state";
  }
  ///@}

  /// The particles as data in this process; null where they live elsewhere
  /// (in a renderer's GPU textures). Their normals are not kept: they do
  /// not feed back into the simulation, and the output computes them from
  /// the positions as it writes them (bp::elementsNormals); Engine::normals()
  /// holds any only after Engine::updateNormals().
  virtual const Engine* particles() { return nullptr; }

  /// Whether the tracer should read the next field time step ahead of need
  /// and offer it (a GPU display uploads it a slab per frame).
  virtual bool readsAhead() const { return false; }
  /// The time step the next update forward will need, once the tracer has
  /// it (an empty slice otherwise).
  virtual void offerUpcoming(const FieldSlice& /*slice*/) {}

  TraceCursor cursor;

protected:
  CheckpointIndex Checkpoints;
};

/// The CPU engine behind the stepper verbs.
class CpuStepper : public Stepper
{
public:
  explicit CpuStepper(RangeRunner run = serialRunner());

  std::string configure(const ElementTemplate& shape, const Parameters& parameters) override;
  std::string setField(const VectorField& field) override;
  void initialize(double startTime) override;
  void step(double t, double h) override;
  void save() override;
  void restore() override;
  void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max) override;
  bool keepsCheckpoints() const override { return true; }
  void keepCheckpoint(long long steps, double time) override;
  void resumeCheckpoint(long long steps) override;
  void dropCheckpoints() override;
  /// The engine's state words an element (Engine::recordWords) times the
  /// whole system's elements.
  double checkpointBytes() const override;
  bool committedState(EngineState& state) override;
  std::string loadState(const EngineState& state) override;
  const Engine* particles() override;

  Engine& engine() { return this->Current; }
  const VectorField* field() const { return this->Field.get(); }
  const RangeRunner& runner() const { return this->Run; }

protected:
  /// Where releases may not land, for the field just set: the field's own
  /// cells here; a distributed run's whole field in DistributedStepper.
  virtual ReleaseMask releaseMaskOf(const VectorField& field, float minSpeed);

private:
  RangeRunner Run;
  Engine Current;
  Engine Saved; ///< save()'s copy: the state, without the step's scratch (Engine.h)
  std::map<long long, Engine> Copies; ///< the checkpoints, by step count
  std::shared_ptr<const VectorField> Field;
  ReleaseMask Release;
  ReleaseMaskSource ReleaseFrom;
};

/**
 * A piece of a distributed run: the CPU engine on this process's piece of the
 * field, owning the elements whose centres lie in its block. A step resets
 * the elements that are due, exchanges those now owned elsewhere (collective:
 * every piece takes every step), then steps; the same arithmetic as a step of
 * the whole system (Engine.h).
 */
class DistributedStepper : public CpuStepper
{
public:
  DistributedStepper(RangeRunner run, ExchangeFunction exchange, ReleaseMaskFunction releaseMask);

  /// Every piece's block and the whole field's domain, both grid-local; this
  /// process's piece. Set before initialize().
  void setPieces(const Partition& partition, const Domain& domain, int piece);

  /// Places every element, then keeps those whose centres lie in this piece.
  void initialize(double startTime) override;
  /// Resets, exchanges elements with the other pieces, then steps.
  void step(double t, double h) override;
  /// Loads the whole state, then keeps the elements whose centres lie in this piece.
  std::string loadState(const EngineState& state) override;

  /// Elements this piece sent away since the count was last taken.
  long long takeMigrated();
  /// The last failed exchange's error since this was last asked (empty when
  /// every exchange went through).
  std::string takeExchangeError();

protected:
  ReleaseMask releaseMaskOf(const VectorField& piece, float minSpeed) override;

private:
  ExchangeFunction Exchange;
  ReleaseMaskFunction WholeReleaseMask;
  std::unique_ptr<Partition> Pieces;
  Domain WholeDomain;
  int Piece = 0;
  long long Migrated = 0;
  std::string Error;
};

} // namespace bp

#endif
