// SPDX-License-Identifier: BSD-3-Clause
// Engine = Automatic: the GPU engine on a hardware renderer only.
#include "EngineChoice.h"
#include "RendererKind.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
TEST(EngineChoice, SoftwareRenderersAreRecognisedByName)
{
  using K = bp::RendererKind;
  EXPECT_EQ(bp::rendererKind("llvmpipe (LLVM 15.0.6, 256 bits)"), K::Software);
  EXPECT_EQ(bp::rendererKind("Mesa X11 (softpipe)"), K::Software);
  EXPECT_EQ(bp::rendererKind("Software Rasterizer"), K::Software);
  EXPECT_EQ(bp::rendererKind("Google SwiftShader"), K::Software);
  EXPECT_EQ(bp::rendererKind("NVIDIA H100 80GB HBM3/PCIe/SSE2"), K::Hardware);
  EXPECT_EQ(bp::rendererKind("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7)"), K::Hardware);
  EXPECT_EQ(bp::rendererKind("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), K::Hardware);
  EXPECT_EQ(bp::rendererKind(""), K::Unknown);
}

TEST(EngineChoice, AutomaticTakesTheGpuOnlyOnHardware)
{
  using C = bp::EngineChoice;
  using K = bp::RendererKind;
  EXPECT_TRUE(bp::usesGpuEngine(C::Automatic, K::Hardware));
  EXPECT_FALSE(bp::usesGpuEngine(C::Automatic, K::Software));
  EXPECT_FALSE(bp::usesGpuEngine(C::Automatic, K::Unknown));
  for (K kind : { K::Hardware, K::Software, K::Unknown })
  {
    EXPECT_TRUE(bp::usesGpuEngine(C::Gpu, kind));
    EXPECT_FALSE(bp::usesGpuEngine(C::Cpu, kind));
  }
}

TEST(EngineChoice, TheNoteOnASoftwareRendererNamesItAndTheWayOut)
{
  const std::string note = bp::automaticOnCpuNote("llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_NE(note.find("software renderer (llvmpipe (LLVM 15.0.6, 256 bits))"), std::string::npos)
    << note;
  EXPECT_NE(note.find("the CPU engine traces"), std::string::npos) << note;
  EXPECT_NE(note.find("Set Engine to GPU"), std::string::npos) << note;
  EXPECT_EQ(note.find('\n'), std::string::npos) << "one line; the display ends it";
}
} // namespace
