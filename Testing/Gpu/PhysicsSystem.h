// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PhysicsSystem.h
 * @brief What the physics tests share: one engine or the other behind the
 * stepper verbs, with the readbacks their checks need.
 */
#ifndef BoundParticles_PhysicsSystem_h
#define BoundParticles_PhysicsSystem_h

#include "Engine.h"
#include "GpuStepper.h"
#include "SharedContext.h"
#include "Stepper.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace bptest
{
/// A physics test run on each engine: its parameter is true for the GPU
/// engine, which needs a headless OpenGL context (a failure without one).
class OnEachEngine : public ::testing::TestWithParam<bool>
{
protected:
  void SetUp() override
  {
    if (GetParam() && !bp::haveSharedContext())
      GTEST_FAIL() << "the GPU engine needs a headless OpenGL context";
  }
  const char* engine() const { return GetParam() ? "GPU" : "CPU"; }
};

/// The engine in a test's name (INSTANTIATE_TEST_SUITE_P): /CPU or /GPU.
inline std::string engineName(const ::testing::TestParamInfo<bool>& info)
{
  return info.param ? "GPU" : "CPU";
}

/// One engine or the other behind the stepper verbs (Core/Stepping/Stepper.h), with
/// the readbacks the checks need.
class System
{
public:
  System(bool gpu, const bp::ElementTemplate& shape, const bp::Parameters& p,
    const bp::VectorField& field)
  {
    if (gpu)
      this->Stepper.reset(this->Gpu = new bp::GpuStepper);
    else
      this->Stepper.reset(this->Cpu = new bp::CpuStepper(bp::serialRunner()));
    EXPECT_EQ(this->Stepper->configure(shape, p), "");
    EXPECT_EQ(this->Stepper->setField(field), "");
    this->Stepper->initialize(0.0);
  }
  ~System()
  {
    if (this->Gpu)
      this->Gpu->engine().release();
  }
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  void step(double t, double h) { this->Stepper->step(t, h); }
  std::vector<float> positions() const
  {
    if (this->Cpu)
      return this->Cpu->engine().positions();
    std::vector<float> p;
    this->Gpu->engine().read(&p, nullptr, nullptr);
    return p;
  }
  /// Engine::poses() and Engine::spins(): 4 floats per element.
  std::vector<float> poses() const { return this->elementQuantity(true); }
  std::vector<float> spins() const { return this->elementQuantity(false); }
  std::vector<float> flags() const
  {
    if (this->Cpu)
      return std::vector<float>(
        this->Cpu->engine().resetFlags().begin(), this->Cpu->engine().resetFlags().end());
    std::vector<float> f;
    this->Gpu->engine().readElements(nullptr, nullptr, nullptr, nullptr, &f);
    return f;
  }

  /// Engine::slips(): each particle's slip velocity, 3 floats (heavy particles).
  std::vector<float> slips() const
  {
    if (this->Cpu)
      return this->Cpu->engine().slips();
    std::vector<float> s;
    this->Gpu->engine().readSlips(s);
    return s;
  }

private:
  std::vector<float> elementQuantity(bool poses) const
  {
    if (this->Cpu)
      return poses ? this->Cpu->engine().poses() : this->Cpu->engine().spins();
    std::vector<float> q;
    this->Gpu->engine().readPoses(poses ? &q : nullptr, poses ? nullptr : &q);
    return q;
  }

  std::unique_ptr<bp::Stepper> Stepper;
  bp::CpuStepper* Cpu = nullptr; // the stepper, when it is this kind
  bp::GpuStepper* Gpu = nullptr;
};
} // namespace bptest

#endif
