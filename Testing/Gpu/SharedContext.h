// SPDX-License-Identifier: BSD-3-Clause
// The one headless OpenGL context a GPU test executable shares across its
// tests (made on first use, kept until exit): contexts are slow to make, and
// a test that needs one fails, with the reason, where none can be made.
#ifndef BoundParticles_SharedContext_h
#define BoundParticles_SharedContext_h

#include "HeadlessContext.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace bp
{
inline bool haveSharedContext()
{
  static std::unique_ptr<HeadlessContext> shared;
  static std::string error = "unset";
  if (!shared)
  {
    shared.reset(new HeadlessContext);
    error = shared->create();
  }
  EXPECT_EQ(error, "") << "no headless OpenGL context";
  return error.empty();
}
} // namespace bp

#endif
