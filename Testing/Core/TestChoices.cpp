// SPDX-License-Identifier: BSD-3-Clause
// Every enumeration a property takes names each of its values: a text that
// is not empty, none twice, one per value from 0 to its last enumerator, and
// "?" for a number past either end. (PropertyDefaults holds the texts to the
// proxy XML's entries.)
#include "BoundParticlesChoices.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace
{
/// The enumeration whose last enumerator is `last`.
template <typename E>
void expectNamed(E last, const char* what)
{
  SCOPED_TRACE(what);
  EXPECT_EQ(bp::enumCount<E>(), int(last) + 1) << "one text per value, up to the last";
  std::set<std::string> texts;
  for (int v = 0; v < bp::enumCount<E>(); ++v)
  {
    const std::string text = bp::enumName(E(v));
    EXPECT_FALSE(text.empty()) << "value " << v;
    EXPECT_NE(text, "?") << "value " << v;
    EXPECT_TRUE(texts.insert(text).second) << "\"" << text << "\" twice";
  }
  EXPECT_STREQ(bp::enumName(E(-1)), "?");
  EXPECT_STREQ(bp::enumName(E(int(last) + 1)), "?");
}

TEST(Choices, EveryValueHasOneTextOfItsOwn)
{
  expectNamed(bp::Integrator::RK4, "Integrator");
  expectNamed(bp::Restoration::ShapeMatching, "Restoration");
  expectNamed(bp::Orientation::AlongFlow, "Orientation");
  expectNamed(bp::ReleasePattern::Lattice, "ReleasePattern");
  expectNamed(bp::Anchor::Centre, "Anchor");
  expectNamed(bp::Inertia::MaxeyRiley, "Inertia");
  expectNamed(bp::ResetWhen::AnyParticleLeaves, "ResetWhen");
  expectNamed(bp::Boundary::Bounce, "Boundary");
  expectNamed(bp::StepUnit::Time, "StepUnit");
  expectNamed(bp::ShapeFit::Linear, "ShapeFit");
  expectNamed(bp::BuiltinShape::Fish, "BuiltinShape");
  expectNamed(bp::MeshSprings::AllPairs, "MeshSprings");
  expectNamed(bp::Linking::Torus, "Linking");
  expectNamed(bp::EngineChoice::Automatic, "EngineChoice");
  expectNamed(bp::AnalyticFlow::DoubleGyre, "AnalyticFlow");
  expectNamed(bp::TimeDirection::Backward, "TimeDirection");
}
} // namespace
