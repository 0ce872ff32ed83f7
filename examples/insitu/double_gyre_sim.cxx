// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file double_gyre_sim.cxx
 * @brief A small C++ simulation that hands its flow to Catalyst one time step
 * at a time, through Catalyst's C++ adaptor API (vtkCPProcessor).
 *
 * The flow is the double gyre (the analytic unsteady flow of
 * double_gyre_sim.py, on the same grid), advanced in time by the loop in
 * main(). At each step the grid goes to Catalyst, where the analysis script
 * (trace_elements.py, a version 2 Catalyst script) traces bound particles
 * through it with the Bound Particle Tracer and writes the elements and a
 * picture every N steps.
 *
 * Under MPI (`mpiexec -n R double_gyre_sim ...`) each process computes and
 * hands over only its piece of the grid: a slab along x with one ghost layer
 * of points on each side, as a finite-difference solver would hold it; the
 * tracer gathers what its own blocks need from the processes' pieces.
 *
 *     double_gyre_sim --plugin BoundParticles.so --script trace_elements.py
 *                     [--steps 50] [--dt 0.2] [--every 10] [--out DIR]
 *                     [--write-steps DIR] [--engine CPU|GPU|Automatic]
 *                     [--checkpoint-every K] [--restart-from N] [--checkpoints DIR]
 *
 * With `--write-steps DIR` it also writes every step it hands over to DIR
 * (`flow.pvd` over `flow_NNNN.pvti`, over a `flow_NNNN_R.vti` piece per
 * process), so the same steps can be traced post hoc.
 *
 * Checkpoint and restart, as double_gyre_sim.py: `--checkpoint-every K`
 * writes the solver's checkpoint every K steps (`checkpoint_NNNN.txt`, its
 * step and time: the flow is analytic) while the analysis script writes the
 * trace's state at the same step; `--restart-from N` starts from checkpoint N
 * (in `--checkpoints DIR`, by default `--out`), handing step N first, and the
 * trace goes on from the state saved there.
 */
#include "vtkCPDataDescription.h"
#include "vtkCPInputDataDescription.h"
#include "vtkCPProcessor.h"
#include "vtkCPPythonScriptV2Pipeline.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkXMLImageDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

#if BOUNDPARTICLES_EXAMPLE_MPI
#include "vtkMPI.h"
#endif

namespace
{
/// The grid of double_gyre_sim.py: points along x, y, z, and the bounds.
constexpr int Dims[3] = { 64, 32, 2 };
constexpr double Bounds[6] = { 0.0, 2.0, 0.0, 1.0, 0.0, 0.05 };
/// Ghost layers of points each process holds beyond its own slab.
constexpr int GhostLayers = 1;

struct Options
{
  std::string plugin, script, out = "insitu-out", writeSteps, engine = "CPU", checkpoints;
  int steps = 50, every = 10, checkpointEvery = 0, restartFrom = -1;
  double dt = 0.2;
};

bool parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--plugin")
      o.plugin = value;
    else if (key == "--script")
      o.script = value;
    else if (key == "--out")
      o.out = value;
    else if (key == "--write-steps")
      o.writeSteps = value;
    else if (key == "--engine")
      o.engine = value;
    else if (key == "--steps")
      o.steps = std::atoi(value.c_str());
    else if (key == "--every")
      o.every = std::atoi(value.c_str());
    else if (key == "--dt")
      o.dt = std::atof(value.c_str());
    else if (key == "--checkpoint-every")
      o.checkpointEvery = std::atoi(value.c_str());
    else if (key == "--restart-from")
      o.restartFrom = std::atoi(value.c_str());
    else if (key == "--checkpoints")
      o.checkpoints = value;
    else
      return false;
  }
  return argc % 2 == 1 && !o.plugin.empty() && !o.script.empty() && o.steps > 0 && o.every > 0 &&
    o.dt > 0.0;
}

/// This process's piece of the whole point extent: a slab along x of the
/// cells (the processes split them evenly), with GhostLayers more points on
/// each side where the grid goes on.
void pieceExtent(int rank, int ranks, int extent[6])
{
  const int cells = Dims[0] - 1;
  const int first = cells * rank / ranks, last = cells * (rank + 1) / ranks;
  extent[0] = std::max(0, first - GhostLayers);
  extent[1] = std::min(Dims[0] - 1, last + GhostLayers);
  extent[2] = 0;
  extent[3] = Dims[1] - 1;
  extent[4] = 0;
  extent[5] = Dims[2] - 1;
}

double spacing(int axis)
{
  return (Bounds[2 * axis + 1] - Bounds[2 * axis]) / (Dims[axis] - 1);
}

/// The double gyre's velocity at (x, y) and time t (A = 0.1, eps = 0.25,
/// omega = pi/5), as double_gyre_sim.py computes it.
void doubleGyre(double x, double y, double t, float velocity[3])
{
  const double pi = 3.14159265358979323846;
  const double a = 0.1, eps = 0.25, omega = pi / 5.0;
  const double at = eps * std::sin(omega * t), bt = 1.0 - 2.0 * eps * std::sin(omega * t);
  const double f = at * x * x + bt * x, dfdx = 2.0 * at * x + bt;
  velocity[0] = float(-pi * a * std::sin(pi * f) * std::cos(pi * y));
  velocity[1] = float(pi * a * std::cos(pi * f) * std::sin(pi * y) * dfdx);
  velocity[2] = 0.0f;
}

/// The simulation's state: its piece of the grid with the velocity at time t.
class Simulation
{
public:
  Simulation(int rank, int ranks)
  {
    int extent[6];
    pieceExtent(rank, ranks, extent);
    this->Grid->SetExtent(extent);
    this->Grid->SetOrigin(Bounds[0], Bounds[2], Bounds[4]);
    this->Grid->SetSpacing(spacing(0), spacing(1), spacing(2));
    this->Velocity->SetName("velocity");
    this->Velocity->SetNumberOfComponents(3);
    this->Velocity->SetNumberOfTuples(this->Grid->GetNumberOfPoints());
    this->Grid->GetPointData()->AddArray(this->Velocity);
  }

  /// Advances the state to time t (here: the analytic flow's value).
  void advanceTo(double t)
  {
    const int* e = this->Grid->GetExtent();
    vtkIdType id = 0;
    for (int k = e[4]; k <= e[5]; ++k)
      for (int j = e[2]; j <= e[3]; ++j)
        for (int i = e[0]; i <= e[1]; ++i)
        {
          float v[3];
          doubleGyre(Bounds[0] + i * spacing(0), Bounds[2] + j * spacing(1), t, v);
          this->Velocity->SetTypedTuple(id++, v);
        }
    this->Velocity->Modified();
  }

  vtkImageData* grid() { return this->Grid; }

private:
  vtkNew<vtkImageData> Grid;
  vtkNew<vtkFloatArray> Velocity;
};

/// Hands one step to Catalyst: the grid named "input", with its whole extent.
void coprocess(vtkCPProcessor* processor, vtkImageData* grid, double time, int step, bool last)
{
  vtkNew<vtkCPDataDescription> description;
  description->AddInput("input");
  description->SetTimeData(time, step);
  description->SetForceOutput(last);
  if (processor->RequestDataDescription(description) == 0)
  {
    return; // no pipeline wants this step
  }
  vtkCPInputDataDescription* input = description->GetInputDescriptionByName("input");
  const int whole[6] = { 0, Dims[0] - 1, 0, Dims[1] - 1, 0, Dims[2] - 1 };
  input->SetWholeExtent(const_cast<int*>(whole));
  input->SetGrid(grid);
  processor->CoProcess(description);
}

/// Writes this process's piece as DIR/flow_NNNN_R.vti and, on process 0,
/// DIR/flow_NNNN.pvti over every process's piece, for a post hoc trace of
/// the same steps. Returns the .pvti's name.
std::string writeStep(const std::string& dir, vtkImageData* grid, int step, int rank, int ranks)
{
  char name[32];
  std::snprintf(name, sizeof(name), "flow_%04d", step);
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName((dir + "/" + name + "_" + std::to_string(rank) + ".vti").c_str());
  writer->Write();
  if (rank == 0)
  {
    std::ofstream pvti(dir + "/" + name + ".pvti");
    pvti.precision(17);
    pvti << "<VTKFile type=\"PImageData\" version=\"0.1\"><PImageData WholeExtent=\"0 "
         << Dims[0] - 1 << " 0 " << Dims[1] - 1 << " 0 " << Dims[2] - 1
         << "\" GhostLevel=\"0\" Origin=\"" << Bounds[0] << " " << Bounds[2] << " " << Bounds[4]
         << "\" Spacing=\"" << spacing(0) << " " << spacing(1) << " " << spacing(2) << "\">\n"
         << "<PPointData><PDataArray type=\"Float32\" Name=\"velocity\" "
            "NumberOfComponents=\"3\"/></PPointData>\n";
    for (int piece = 0; piece < ranks; ++piece)
    {
      int e[6];
      pieceExtent(piece, ranks, e);
      pvti << "<Piece Extent=\"" << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4]
           << " " << e[5] << "\" Source=\"" << name << "_" << piece << ".vti\"/>\n";
    }
    pvti << "</PImageData></VTKFile>\n";
  }
  return std::string(name) + ".pvti";
}

/// The solver's checkpoint at `step` in `dir`: the flow is analytic, so its
/// step and time are all of the solver's state.
std::string checkpointName(const std::string& dir, int step)
{
  char name[32];
  std::snprintf(name, sizeof(name), "checkpoint_%04d.txt", step);
  return dir + "/" + name;
}

void writeCheckpoint(const std::string& dir, int step, double time)
{
  std::ofstream checkpoint(checkpointName(dir, step));
  checkpoint.precision(17);
  checkpoint << step << " " << time << "\n";
}

/// The step checkpoint `step` in `dir` restarts from; -1 if it cannot be read.
int readCheckpoint(const std::string& dir, int step)
{
  std::ifstream checkpoint(checkpointName(dir, step));
  int saved = -1;
  double time = 0.0;
  return (checkpoint >> saved >> time) ? saved : -1;
}

void writeCollection(
  const std::string& dir, const std::vector<std::pair<double, std::string>>& steps)
{
  std::ofstream pvd(dir + "/flow.pvd");
  pvd << "<VTKFile type=\"Collection\" version=\"0.1\"><Collection>\n";
  pvd.precision(17);
  for (const auto& step : steps)
  {
    pvd << "<DataSet timestep=\"" << step.first << "\" file=\"" << step.second << "\"/>\n";
  }
  pvd << "</Collection></VTKFile>\n";
}
} // namespace

int main(int argc, char* argv[])
{
  int rank = 0, ranks = 1;
#if BOUNDPARTICLES_EXAMPLE_MPI
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
#endif
  Options options;
  if (!parse(argc, argv, options))
  {
    if (rank == 0)
    {
      std::cerr << "usage: " << argv[0]
                << " --plugin BoundParticles.so --script trace_elements.py [--steps 50]"
                   " [--dt 0.2] [--every 10] [--out DIR] [--write-steps DIR]"
                   " [--engine CPU|GPU|Automatic] [--checkpoint-every K] [--restart-from N]"
                   " [--checkpoints DIR]\n";
    }
#if BOUNDPARTICLES_EXAMPLE_MPI
    MPI_Finalize();
#endif
    return 2;
  }
  // The analysis script reads its settings from the environment, as with
  // double_gyre_sim.py.
  ::mkdir(options.out.c_str(), 0777);
  if (!options.writeSteps.empty())
  {
    ::mkdir(options.writeSteps.c_str(), 0777);
  }
  char outPath[4096];
  const std::string out = ::realpath(options.out.c_str(), outPath) ? outPath : options.out;
  ::setenv("BOUNDPARTICLES_PLUGIN", options.plugin.c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_OUT", out.c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_EVERY", std::to_string(options.every).c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_LAST", std::to_string(options.steps - 1).c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_ENGINE", options.engine.c_str(), 1);
  const std::string given = options.checkpoints.empty() ? options.out : options.checkpoints;
  ::mkdir(given.c_str(), 0777);
  const std::string checkpoints = ::realpath(given.c_str(), outPath) ? outPath : given;
  ::setenv(
    "BOUNDPARTICLES_INSITU_CHECKPOINT_EVERY", std::to_string(options.checkpointEvery).c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_CHECKPOINTS", checkpoints.c_str(), 1);
  ::setenv("BOUNDPARTICLES_INSITU_RESTART", std::to_string(options.restartFrom).c_str(), 1);
  // The solver goes on from its checkpoint: the restart step is handed first.
  const int first = options.restartFrom >= 0 ? readCheckpoint(checkpoints, options.restartFrom) : 0;

  int failed = 0;
  {
    // ParaView is initialized by the processor (in batch mode, symmetric
    // under MPI) before the pipeline brings up Python, whose paraview module
    // would otherwise initialize it as a one-process client.
    vtkNew<vtkCPProcessor> processor;
    const bool started = processor->Initialize() != 0;
    vtkNew<vtkCPPythonScriptV2Pipeline> pipeline;
    if (first < 0)
    {
      std::cerr << "no checkpoint " << options.restartFrom << " in " << checkpoints << "\n";
      failed = 1;
    }
    else if (!started || !pipeline->Initialize(options.script.c_str()))
    {
      std::cerr << "Catalyst could not start with the script " << options.script << "\n";
      failed = 1;
    }
    else
    {
      processor->AddPipeline(pipeline);
      Simulation simulation(rank, ranks);
      std::vector<std::pair<double, std::string>> written;
      for (int step = first; step < options.steps; ++step)
      {
        const double time = step * options.dt;
        simulation.advanceTo(time);
        coprocess(processor, simulation.grid(), time, step, step == options.steps - 1);
        if (options.checkpointEvery > 0 && step % options.checkpointEvery == 0 && step > first &&
          rank == 0)
        {
          writeCheckpoint(checkpoints, step, time);
        }
        if (!options.writeSteps.empty())
        {
          written.emplace_back(
            time, writeStep(options.writeSteps, simulation.grid(), step, rank, ranks));
        }
      }
      if (!options.writeSteps.empty() && rank == 0)
      {
        writeCollection(options.writeSteps, written);
      }
    }
    processor->Finalize();
  }
#if BOUNDPARTICLES_EXAMPLE_MPI
  MPI_Finalize();
#endif
  return failed;
}
