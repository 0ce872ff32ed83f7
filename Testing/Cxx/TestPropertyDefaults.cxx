// SPDX-License-Identifier: BSD-3-Clause
// The ServerManager XML, the VTK classes and Core cannot disagree. Every
// property of every proxy of the plugin's XML (Plugin/BoundParticles.xml,
// Plugin/BoundParticlesReaders.xml) has one verdict:
// - checked against the class: a fresh object's getter (GetX, GetXAsString
//   for an enumeration, a text getter for a string, every component of a
//   vector), read through the plugin's ClientServer wrapping as ParaView
//   calls the class, starts at the XML's default; the setter keeps every
//   component of both ends of the XML's range, and a boolean's 0 and 1; the
//   default lies in the range; an enumeration's values are
//   distinct, its default among them, its setter keeps each value offered and
//   none past them, and says each as the entry's text. The display's setters
//   that hand their value to its actor, vtkProperty or mapper are read back
//   from those (ForwardedByTheDisplay);
// - also against Core where the property maps to Core: a tracer property's
//   default is a new bpvtk::TracerConfig's (bp::TraceSettings,
//   bp::Parameters), and an enumeration's entries, value and text, are its
//   Core enumeration's (bp::EnumTraits<E>::names, E the class's typed getter's);
// - or exempt, with why (Exempt).
// A property with no verdict fails, and so does a table entry that names no
// property. The test reads the XML where it is written (Plugin/), so that an
// edit is checked without a new build.
#include "PropertyDefaultsHelpers.h"

#include "vtkAnalyticFlowSource.h"
#include "vtkBoundParticleTracer.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkProperty.h"

#include "BoundParticlesChoices.h"
#include "EngineParameters.h"
#include "ReleaseLattice.h"
#include "TraceSettings.h"
#include "TracerConfig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

using pdt::numbers;

namespace
{
const char* const Tracer = "BoundParticleTracer";
const char* const Display = "vtkBoundParticleRepresentation";

/// The properties with no default of their own to compare, and why.
const std::map<std::string, std::string> Exempt = {
  { "AnalyticFlow.TimestepValues", "information, the time line" },
  { "AnalyticFlow.TimeRange", "information, the time line" },
  { "BoundParticleTracer.Input", "an input" },
  { "BoundParticleTracer.ElementTemplate", "an input" },
  { "BoundParticleTracer.SeedSource", "an input" },
  { "BoundParticleTracer.Surfaces", "an input" },
  { "BoundParticleTracer.Vectors", "an array of the input, chosen by its domain; no default" },
  { "BoundParticleTracer.ReleaseWeights", "an array of the input, None unless chosen" },
  { "BoundParticleTracer.UnitsMismatchedVectors", "information, from the input" },
  { "BoundParticleTracer.UnitsFittingVectors", "information, from the input" },
  { "BoundParticleTracer.SeedType", "a proxy (none: the emitter box)" },
  { "BoundParticleTracer.EmitterBoxUseReferenceBounds", "the box widget's, no command" },
  { "BoundParticleTracer.EmitterBoxReferenceBounds", "the box widget's, no command" },
  { "BoundParticleTracer.OutputArrayInfo", "information, the table of bp::outputArrays()" },
  { "BoundParticleTracer.OutputArrays",
    "a selection, defaulted from the table (TestTracerOutput)" },
  { "BoundParticleTracer.ResolvedTimeStep", "information, what the last update resolved" },
  { "BoundParticleTracer.ResolvedElementSize", "information, what the last update resolved" },
  { "BoundParticleTracer.SimulationTime", "information, what the last update did" },
  { "BoundParticleTracer.StepsInLastUpdate", "information, what the last update did" },
  { "BoundParticleTracer.CheckpointSpacing", "information, what the last update did" },
  { "BoundParticleTracer.LastUpdateReplayed", "information, what the last update did" },
  { "BoundParticleTracer.TimestepValues", "information, the time line" },
  { "BoundParticleTracer.TimeRange", "information, the time line" },
  { "PointCloud.Input", "the tracer's input, linked, for the widget's bounds" },
  { "Line.Input", "the tracer's input, linked, for the widget's bounds" },
  { "PointCloud.SeedSource", "the tracer's Seed Source, linked, to hide the widgets it replaces" },
  { "Line.SeedSource", "the tracer's Seed Source, linked, to hide the widgets it replaces" },
  { "BoundParticlesRepresentation.Input", "an input" },
  { "BoundParticlesRepresentation.ColorArrayName", "an array of the input; none: solid colour" },
  { "BoundParticlesRepresentation.LookupTable", "a proxy" },
  { "RawVectorVolumeSeriesReader.TimestepValues", "information, the time line" },
  { "RawVectorVolumeSeriesReader.TimeRange", "information, the time line" },
};

/// The display's setters that hand their value straight to its actor, the
/// actor's vtkProperty or its CPU mapper, and how to read it back there.
const std::map<std::string, pdt::DisplayGetter>& ForwardedByTheDisplay = pdt::displayGetters();

template <typename T>
std::vector<double> one(T value)
{
  return { double(value) };
}
template <typename T, std::size_t N>
std::vector<double> all(const std::array<T, N>& values)
{
  return std::vector<double>(values.begin(), values.end());
}

/// Each tracer property that Core holds, and its field in a new
/// bpvtk::TracerConfig (the bp::TraceSettings and bp::Parameters the engine
/// starts from when nothing sets them): Core's default must be the panel's.
using CoreField = std::function<std::vector<double>(const bpvtk::TracerConfig&)>;
const std::map<std::string, CoreField> CoreDefaults = {
  { "ResampleDimensions", [](const auto& c) { return all(c.resampleDimensions); } },
  { "ElementShape", [](const auto& c) { return one(c.shape); } },
  { "TemplateSprings", [](const auto& c) { return one(c.templateSprings); } },
  { "NumberOfElements", [](const auto& c) { return one(c.trace.numberOfElements); } },
  { "ElementSize", [](const auto& c) { return one(c.trace.elementSize); } },
  { "ReleaseOrientation", [](const auto& c) { return one(c.trace.engine.orientation); } },
  { "ElementRotation", [](const auto& c) { return all(c.trace.rotationDegrees); } },
  { "ReleasePattern", [](const auto& c) { return one(c.trace.engine.releasePattern); } },
  { "LatticeSpacing", [](const auto& c) { return one(c.trace.latticeSpacing); } },
  { "EmitterCenter", [](const auto& c) { return all(c.trace.emitterCenter); } },
  { "EmitterSize", [](const auto& c) { return all(c.trace.emitterSize); } },
  { "Engine", [](const auto& c) { return one(c.engine); } },
  { "StepSize", [](const auto& c) { return one(c.trace.stepSize); } },
  { "StepSizeUnit",
    [](const auto& c)
    { return one(c.trace.stepInCellLengths ? bp::StepUnit::CellLength : bp::StepUnit::Time); } },
  { "Integrator", [](const auto& c) { return one(c.trace.engine.integrator); } },
  { "TimeDirection", [](const auto& c) { return one(c.trace.timeDirection); } },
  { "Restoration", [](const auto& c) { return one(c.trace.engine.restoration); } },
  { "RestorationIterations", [](const auto& c) { return one(c.trace.engine.iterations); } },
  { "RelaxationFactor", [](const auto& c) { return one(c.trace.engine.relaxation); } },
  { "ShapeMatchingStiffness", [](const auto& c) { return one(c.trace.engine.shapeStiffness); } },
  { "ShapeMatchingMode",
    [](const auto& c) {
      return one(c.trace.engine.linearShapeMatching ? bp::ShapeFit::Linear : bp::ShapeFit::Rigid);
    } },
  { "LinearShapeMatchingBeta", [](const auto& c) { return one(c.trace.engine.linearBlend); } },
  { "Anchor", [](const auto& c) { return one(c.trace.engine.anchor); } },
  { "Inertia", [](const auto& c) { return one(c.trace.engine.inertia); } },
  { "ResponseTime", [](const auto& c) { return one(c.trace.engine.responseTime); } },
  { "DensityRatio", [](const auto& c) { return one(c.trace.engine.densityRatio); } },
  { "Gravity", [](const auto& c) { return all(c.trace.engine.gravity); } },
  { "Linking", [](const auto& c) { return one(c.trace.engine.linking); } },
  { "LatticeWidth", [](const auto& c) { return one(c.trace.engine.latticeWidth); } },
  { "LinkStiffness", [](const auto& c) { return one(c.trace.engine.linkStiffness); } },
  { "ResetWhen", [](const auto& c) { return one(c.trace.engine.resetWhen); } },
  { "Boundary", [](const auto& c) { return one(c.trace.engine.boundary); } },
  { "Restitution", [](const auto& c) { return one(c.trace.engine.restitution); } },
  { "Periodic", [](const auto& c) { return all(c.periodic); } },
  { "MinimumReleaseSpeed", [](const auto& c) { return one(c.trace.minimumReleaseSpeed); } },
  { "Trails", [](const auto& c) { return one(c.trace.trailLength > 0 ? 1 : 0); } },
  { "TrailSpacing", [](const auto& c) { return one(c.trace.trailSpacing); } },
  { "LifetimeRange", [](const auto& c) { return all(c.trace.lifetimeRange); } },
  { "Seed", [](const auto& c) { return one(c.trace.engine.seed); } },
  { "ColoringAxis", [](const auto& c) { return one(c.coloringAxis); } },
  { "CheckpointMemory", [](const auto& c) { return one(c.checkpointMemory); } },
};

/// The tracer's properties checked against the class that Core does not
/// hold as the panel does, and why.
const std::map<std::string, std::string> NotInCore = {
  { "Duration", "the time line's, read in RequestInformation" },
  { "NumberOfTimeSteps", "the time line's, read in RequestInformation" },
  { "FramesPerInputStep", "the time line's, read in RequestInformation" },
  { "ReleaseWindow", "Core holds the window's ends, infinite while it is off" },
  { "ReleaseStart", "Core holds -infinity while Release Window is off" },
  { "ReleaseStop", "Core holds +infinity while Release Window is off" },
  { "TrailLength", "Core holds 0 while Trails is off" },
  { "ComputeVorticity", "folded into TracerConfig::wanted (Vorticity)" },
  { "InitialStateFile", "a file the tracer reads (TracerConfig::initialStateFile), not a setting" },
  { "SurfaceInteraction", "made per triangle of the Surfaces (Parameters::surfaces)" },
  { "SurfaceInteractionArray",
    "an array of the Surfaces, read per cell into Parameters::surfaces" },
};

/// A Core enumeration's entries, value: text (bp::EnumTraits<E>::names).
using CoreEntries = std::map<int, std::string> (*)();
template <typename E>
std::map<int, std::string> coreEntries()
{
  std::map<int, std::string> entries;
  for (int v = 0; v < bp::enumCount<E>(); ++v)
  {
    entries[v] = bp::EnumTraits<E>::names[v];
  }
  return entries;
}
/// The entries of the Core enumeration E that the class's typed getter
/// `E GetX() const` (vtkBPEnumMacro) returns: the header says which.
template <typename C, typename E>
CoreEntries entriesOfGetter(E (C::*)() const)
{
  return &coreEntries<E>;
}

/// The enumerated properties whose values are a Core enumeration's
/// (Core/Choices/BoundParticlesChoices.h), through the class's typed getter.
using vtkBPT = vtkBoundParticleTracer;
const std::map<std::string, CoreEntries> CoreEnums = {
  { "AnalyticFlow.Flow", entriesOfGetter(&vtkAnalyticFlowSource::GetFlow) },
  { "BoundParticleTracer.ElementShape", entriesOfGetter(&vtkBPT::GetElementShape) },
  { "BoundParticleTracer.TemplateSprings", entriesOfGetter(&vtkBPT::GetTemplateSprings) },
  { "BoundParticleTracer.ReleaseOrientation", entriesOfGetter(&vtkBPT::GetReleaseOrientation) },
  { "BoundParticleTracer.ReleasePattern", entriesOfGetter(&vtkBPT::GetReleasePattern) },
  { "BoundParticleTracer.Engine", entriesOfGetter(&vtkBPT::GetEngine) },
  { "BoundParticleTracer.StepSizeUnit", entriesOfGetter(&vtkBPT::GetStepSizeUnit) },
  { "BoundParticleTracer.ShapeMatchingMode", entriesOfGetter(&vtkBPT::GetShapeMatchingMode) },
  { "BoundParticleTracer.Integrator", entriesOfGetter(&vtkBPT::GetIntegrator) },
  { "BoundParticleTracer.TimeDirection", entriesOfGetter(&vtkBPT::GetTimeDirection) },
  { "BoundParticleTracer.Restoration", entriesOfGetter(&vtkBPT::GetRestoration) },
  { "BoundParticleTracer.Anchor", entriesOfGetter(&vtkBPT::GetAnchor) },
  { "BoundParticleTracer.Inertia", entriesOfGetter(&vtkBPT::GetInertia) },
  { "BoundParticleTracer.Linking", entriesOfGetter(&vtkBPT::GetLinking) },
  { "BoundParticleTracer.ResetWhen", entriesOfGetter(&vtkBPT::GetResetWhen) },
  { "BoundParticleTracer.Boundary", entriesOfGetter(&vtkBPT::GetBoundary) },
  { "BoundParticleTracer.SurfaceInteraction", entriesOfGetter(&vtkBPT::GetSurfaceInteraction) },
};

/// The enumerated properties with no Core enumeration, and why.
const std::map<std::string, std::string> NoCoreChoice = {
  { "BoundParticleTracer.ColoringAxis", "an axis, 0 to 2 (a clamped int)" },
  { "BoundParticlesRepresentation.Interpolation",
    "vtkProperty's values and texts (TheDisplaysInterpolationIsVtkPropertys)" },
};

/// A fresh object of the class, with the display's objects where it is the
/// display.
struct Fresh
{
  vtkTypeUInt32 Id = 0;
  pdt::DisplayObjects Objects;
};
Fresh fresh(const std::string& className)
{
  Fresh object;
  object.Id = pdt::classes().create(className, className == Display ? &object.Objects : nullptr);
  return object;
}

/// What the object's getter for `setter` returns: the class's own, or for a
/// setter the display forwards, the forwarded object's.
bool read(const std::string& className, const Fresh& object, const std::string& setter,
  std::vector<double>& values)
{
  if (className == Display && ForwardedByTheDisplay.count(setter))
  {
    const pdt::DisplayObjects& objects = object.Objects;
    if (!objects.Actor || !objects.Property || !objects.Mapper)
    {
      ADD_FAILURE() << "the display's actor, vtkProperty or mapper was not caught";
      return false;
    }
    values = ForwardedByTheDisplay.at(setter)(objects);
    return true;
  }
  if (!pdt::classes().get(object.Id, "Get" + setter.substr(3), values))
  {
    ADD_FAILURE() << className << " has no Get" << setter.substr(3)
                  << ": add one, or exempt the property (Exempt) with why";
    return false;
  }
  return true;
}

/// A boolean's class keeps both 0 and 1 (the panel's check box).
void checkBoolean(const std::string& key, const std::string& className, vtkXMLDataElement* property)
{
  if (!property->FindNestedElementWithName("BooleanDomain"))
  {
    return;
  }
  const std::string setter = property->GetAttribute("command");
  for (double value : { 0.0, 1.0 })
  {
    const Fresh object = fresh(className);
    std::vector<double> kept;
    ASSERT_TRUE(pdt::classes().set(object.Id, setter, { value }, true)) << setter;
    ASSERT_TRUE(read(className, object, setter, kept));
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0], value) << key << ": " << setter << "(" << value << ") keeps " << kept[0];
  }
}

/// The class keeps each component of both ends of the range the XML's panel
/// offers (a setter that clamps tighter would take a value the panel shows
/// away from it), the other components at their defaults.
void checkRange(const std::string& key, const std::string& className, vtkXMLDataElement* property,
  const std::vector<double>& declared)
{
  vtkXMLDataElement* range = property->FindNestedElementWithName("IntRangeDomain");
  const bool integer = range != nullptr;
  range = range ? range : property->FindNestedElementWithName("DoubleRangeDomain");
  if (!range)
  {
    return;
  }
  const std::string setter = property->GetAttribute("command");
  for (const char* end : { "min", "max" })
  {
    const std::vector<double> ends =
      numbers(range->GetAttribute(end) ? range->GetAttribute(end) : "");
    EXPECT_LE(ends.size(), declared.size())
      << key << ": the range's " << end << " has more components than the property";
    for (std::size_t k = 0; k < ends.size() && k < declared.size(); ++k)
    {
      EXPECT_TRUE(std::string(end) == "min" ? declared[k] >= ends[k] : declared[k] <= ends[k])
        << key << ": component " << k << " of the default, " << declared[k]
        << ", is outside the range (its " << end << " is " << ends[k] << ")";
      std::vector<double> values = declared;
      values[k] = ends[k];
      const Fresh object = fresh(className);
      std::vector<double> kept;
      ASSERT_TRUE(pdt::classes().set(object.Id, setter, values, integer)) << setter;
      ASSERT_TRUE(read(className, object, setter, kept));
      ASSERT_EQ(kept.size(), declared.size());
      EXPECT_EQ(kept[k], ends[k]) << key << ": " << setter << " turns component " << k
                                  << " of the range's " << end << ", " << ends[k] << ", into "
                                  << kept[k];
    }
  }
}

/// Checks the property against a fresh object of the class; false where it
/// could not be (said).
bool checkAgainstTheClass(
  const std::string& key, const std::string& className, vtkXMLDataElement* property)
{
  const char* command = property->GetAttribute("command");
  if (!command || std::string(command).rfind("Set", 0) != 0)
  {
    ADD_FAILURE() << "a property with no verdict: no setter to check it by; exempt it (Exempt) "
                     "with why";
    return false;
  }
  const std::string setter = command;
  const char* text = property->GetAttribute("default_values");
  const Fresh object = fresh(className);
  if (object.Id == 0)
  {
    ADD_FAILURE() << "the wrapping makes no " << className;
    return false;
  }
  if (std::string(property->GetName()) == "StringVectorProperty")
  {
    std::string value;
    if (!pdt::classes().getString(object.Id, "Get" + setter.substr(3), value))
    {
      ADD_FAILURE() << className << " has no text getter Get" << setter.substr(3);
      return false;
    }
    EXPECT_EQ(value, text ? text : "") << key << ": the XML's default is \"" << (text ? text : "")
                                       << "\", " << className << " starts at \"" << value << "\"";
    return true;
  }
  if (!text)
  {
    ADD_FAILURE() << "no default_values";
    return false;
  }
  const std::vector<double> declared = numbers(text);
  int elements = 0;
  if (property->GetScalarAttribute("number_of_elements", elements))
  {
    EXPECT_EQ(declared.size(), std::size_t(elements)) << "default_values \"" << text << "\"";
  }
  if (vtkXMLDataElement* domain = pdt::enumeration(property))
  {
    pdt::checkEntries(key, domain, declared.at(0));
    const std::map<int, std::string> offered = pdt::entriesOf(domain);
    std::string said;
    const bool forwarded = className == Display && ForwardedByTheDisplay.count(setter);
    const bool asText = !forwarded &&
      pdt::classes().getString(object.Id, "Get" + setter.substr(3) + "AsString", said);
    if (!forwarded)
    {
      pdt::checkEnumeration(key, fresh(className).Id, setter, offered, asText);
    }
    if (asText)
    {
      // The typed getter is C++ only: the default is compared as text.
      const auto entry = offered.find(int(declared.at(0)));
      const std::string expected = entry != offered.end() ? entry->second : "?";
      EXPECT_EQ(said, expected) << key << ": the XML's default is \"" << expected << "\", "
                                << className << " starts at \"" << said << "\"";
      return true;
    }
  }
  std::vector<double> actual;
  if (!read(className, object, setter, actual))
  {
    return false;
  }
  EXPECT_EQ(actual.size(), declared.size()) << "components";
  for (std::size_t k = 0; k < actual.size() && k < declared.size(); ++k)
  {
    EXPECT_NEAR(actual[k], declared[k], 1e-12 * std::max(1.0, std::abs(declared[k])))
      << key << ", component " << k << ": the XML's default is " << declared[k] << ", " << className
      << " starts at " << actual[k];
  }
  checkRange(key, className, property, declared);
  checkBoolean(key, className, property);
  return true;
}

/// A tracer property's default is Core's (a new bpvtk::TracerConfig).
void checkCoreDefault(const std::string& name, vtkXMLDataElement* property)
{
  const bpvtk::TracerConfig fresh;
  const std::vector<double> declared = numbers(property->GetAttribute("default_values"));
  const std::vector<double> core = CoreDefaults.at(name)(fresh);
  ASSERT_EQ(core.size(), declared.size());
  for (std::size_t k = 0; k < core.size(); ++k)
  {
    // Core holds many of them as float.
    EXPECT_NEAR(core[k], declared[k], 1e-6 * std::max(1.0, std::abs(declared[k])))
      << Tracer << "." << name << ", component " << k << ": the XML's default is " << declared[k]
      << ", Core's (bpvtk::TracerConfig) " << core[k];
  }
}

struct Tally
{
  std::set<std::string> Proxies;
  std::set<std::string> Properties; // "Proxy.Property"
  std::set<std::string> Setters;    // the display's
  int AgainstTheClass = 0, AlsoCore = 0, Exempted = 0;
};

/// Gives each property of each proxy of the file its verdict.
void checkFile(const std::string& path, Tally& tally)
{
  SCOPED_TRACE(path);
  const pdt::XmlFile file = pdt::readXml(path);
  ASSERT_TRUE(file.Root) << "cannot read " << path;
  for (const pdt::Proxy& proxy : file.Proxies)
  {
    SCOPED_TRACE(proxy.Group + "/" + proxy.Name);
    std::vector<vtkXMLDataElement*> properties;
    for (int i = 0; i < proxy.Element->GetNumberOfNestedElements(); ++i)
    {
      if (pdt::isProperty(proxy.Element->GetNestedElement(i)))
      {
        properties.push_back(proxy.Element->GetNestedElement(i));
      }
    }
    if (proxy.ClassName.empty())
    {
      EXPECT_TRUE(properties.empty()) << "properties on a proxy with no class";
      continue;
    }
    EXPECT_TRUE(pdt::classes().knows(proxy.ClassName))
      << "the plugin's wrapping makes no " << proxy.ClassName;
    EXPECT_TRUE(tally.Proxies.insert(proxy.Name).second) << "a second proxy " << proxy.Name;
    for (vtkXMLDataElement* property : properties)
    {
      const char* name = property->GetAttribute("name");
      ASSERT_TRUE(name) << "a property with no name";
      const std::string key = proxy.Name + "." + name;
      SCOPED_TRACE(key);
      EXPECT_TRUE(tally.Properties.insert(key).second) << "a second property " << key;
      const bool tracer = proxy.Name == Tracer;
      const bool coreDefault = tracer && CoreDefaults.count(name);
      const auto coreEnum = CoreEnums.find(key);
      if (Exempt.count(key))
      {
        EXPECT_FALSE(coreDefault || coreEnum != CoreEnums.end() || NoCoreChoice.count(key) ||
          (tracer && NotInCore.count(name)))
          << "exempt, and yet in a table of Core";
        ++tally.Exempted;
        continue;
      }
      if (proxy.ClassName == Display && property->GetAttribute("command"))
      {
        tally.Setters.insert(property->GetAttribute("command"));
      }
      if (!checkAgainstTheClass(key, proxy.ClassName, property))
      {
        continue;
      }
      ++tally.AgainstTheClass;
      if (vtkXMLDataElement* domain = pdt::enumeration(property))
      {
        EXPECT_TRUE(coreEnum != CoreEnums.end() || NoCoreChoice.count(key))
          << "an enumeration with no Core enumeration: add its enum to "
             "BoundParticlesChoices.h and it to CoreEnums, or it to NoCoreChoice with why";
        if (coreEnum != CoreEnums.end())
        {
          pdt::checkCoreEntries(key, pdt::entriesOf(domain), coreEnum->second());
        }
      }
      else
      {
        EXPECT_TRUE(coreEnum == CoreEnums.end()) << "in CoreEnums, and no enumeration";
      }
      if (tracer)
      {
        EXPECT_NE(coreDefault, NotInCore.count(name) == 1)
          << "a tracer property is either in CoreDefaults (Core's default) or in NotInCore "
             "(with why), once";
      }
      if (coreDefault)
      {
        checkCoreDefault(name, property);
      }
      tally.AlsoCore += coreDefault || coreEnum != CoreEnums.end() ? 1 : 0;
    }
  }
}

/// Each name of `table` is among `seen`, with `prefix` before it.
template <typename Table>
void expectAllSeen(const Table& table, const std::set<std::string>& seen, const char* what,
  const std::string& prefix = "")
{
  for (const auto& entry : table)
  {
    EXPECT_TRUE(seen.count(prefix + entry.first))
      << what << " names " << entry.first << ", which the XML does not have";
  }
}
} // namespace

TEST(PropertyDefaults, EveryPropertyOfEveryProxyHasOneVerdict)
{
  Tally tally;
  checkFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml", tally);
  checkFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticlesReaders.xml", tally);
  expectAllSeen(Exempt, tally.Properties, "Exempt");
  expectAllSeen(CoreEnums, tally.Properties, "CoreEnums");
  expectAllSeen(NoCoreChoice, tally.Properties, "NoCoreChoice");
  expectAllSeen(CoreDefaults, tally.Properties, "CoreDefaults", std::string(Tracer) + ".");
  expectAllSeen(NotInCore, tally.Properties, "NotInCore", std::string(Tracer) + ".");
  expectAllSeen(ForwardedByTheDisplay, tally.Setters, "ForwardedByTheDisplay");
  EXPECT_EQ(int(tally.Properties.size()), tally.AgainstTheClass + tally.Exempted)
    << "a property with no verdict";
  std::printf("TestPropertyDefaults: %zu properties of %zu proxies: %d against the class, %d "
              "also against Core, %d exempt\n",
    tally.Properties.size(), tally.Proxies.size(), tally.AgainstTheClass, tally.AlsoCore,
    tally.Exempted);
}

namespace
{
/// Each GenericDecorator under `element`, however deep (a CompositeDecorator
/// nests them).
void genericDecorators(vtkXMLDataElement* element, std::vector<vtkXMLDataElement*>& found)
{
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* nested = element->GetNestedElement(i);
    const char* type = nested->GetAttribute("type");
    if (std::string(nested->GetName()) == "PropertyWidgetDecorator" && type &&
      std::string(type) == "GenericDecorator")
    {
      found.push_back(nested);
    }
    genericDecorators(nested, found);
  }
}

/// The property of the proxy of the file, or null.
vtkXMLDataElement* findProperty(
  const pdt::XmlFile& file, const std::string& proxyName, const std::string& name)
{
  for (const pdt::Proxy& proxy : file.Proxies)
  {
    for (int i = 0; proxy.Name == proxyName && i < proxy.Element->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* property = proxy.Element->GetNestedElement(i);
      const char* found = property->GetAttribute("name");
      if (pdt::isProperty(property) && found && name == found)
      {
        return property;
      }
    }
  }
  return nullptr;
}
} // namespace

TEST(PropertyDefaults, EveryDecoratorNamesAValueItsPropertyTakes)
{
  const pdt::XmlFile file = pdt::readXml(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
  ASSERT_TRUE(file.Root);
  int checked = 0;
  for (const pdt::Proxy& proxy : file.Proxies)
  {
    std::vector<vtkXMLDataElement*> decorators;
    genericDecorators(proxy.Element, decorators);
    for (vtkXMLDataElement* decorator : decorators)
    {
      const char* name = decorator->GetAttribute("property");
      ASSERT_TRUE(name) << "a GenericDecorator without its property";
      SCOPED_TRACE(proxy.Name + ": decorator on " + name);
      vtkXMLDataElement* property =
        proxy.Element->FindNestedElementWithNameAndAttribute("IntVectorProperty", "name", name);
      ASSERT_TRUE(property) << "no IntVectorProperty " << name << " in the proxy";
      std::set<int> taken;
      if (vtkXMLDataElement* domain = pdt::enumeration(property))
      {
        for (const auto& entry : pdt::entriesOf(domain))
        {
          taken.insert(entry.first);
        }
      }
      else
      {
        ASSERT_TRUE(property->FindNestedElementWithName("BooleanDomain"))
          << name << " is neither an enumeration nor a boolean";
        taken = { 0, 1 };
      }
      const char* values = decorator->GetAttribute("values");
      const char* value = decorator->GetAttribute("value");
      const std::vector<double> named = numbers(values ? values : value ? value : "");
      EXPECT_FALSE(named.empty()) << "names no value";
      for (double v : named)
      {
        EXPECT_TRUE(taken.count(int(v)) && v == int(v)) << name << " takes no value " << v;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  std::printf("%d decorators checked\n", checked);
}

TEST(PropertyDefaults, TheDisplaysInterpolationIsVtkPropertys)
{
  // The display hands Interpolation to its actor's vtkProperty: the XML's
  // entries are vtkProperty's values and texts.
  const pdt::XmlFile file = pdt::readXml(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
  vtkXMLDataElement* interpolation =
    findProperty(file, "BoundParticlesRepresentation", "Interpolation");
  ASSERT_TRUE(interpolation && pdt::enumeration(interpolation));
  vtkNew<vtkProperty> property;
  for (const auto& [value, text] : pdt::entriesOf(pdt::enumeration(interpolation)))
  {
    property->SetInterpolation(value);
    EXPECT_EQ(property->GetInterpolation(), value);
    EXPECT_STREQ(property->GetInterpolationAsString(), text.c_str()) << "value " << value;
  }
}

TEST(PropertyDefaults, TheXmlsMaximaAreCoresLimits)
{
  // A range's maximum that mirrors a limit Core enforces is that limit: the
  // panel offers exactly what the engine takes. (Line.Resolution has no
  // maximum: its releases take the first bp::MaxSeedPoints points, said.)
  const std::map<std::pair<std::string, std::string>, double> limits = {
    { { Tracer, "TrailLength" }, bp::MaxTrailLength },
    { { Tracer, "TrailSpacing" }, bp::MaxTrailSpacing },
    { { Tracer, "FramesPerInputStep" }, bp::MaxFramesPerInterval },
    { { Tracer, "NumberOfElements" }, bp::MaxLatticeCount },
    { { "PointCloud", "NumberOfPoints" }, double(bp::MaxSeedPoints) },
    { { "Surface", "NumberOfPoints" }, double(bp::MaxSeedPoints) },
  };
  const pdt::XmlFile file = pdt::readXml(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
  for (const auto& [key, limit] : limits)
  {
    SCOPED_TRACE(key.first + "." + key.second);
    vtkXMLDataElement* property = findProperty(file, key.first, key.second);
    ASSERT_TRUE(property) << "no such property";
    vtkXMLDataElement* range = property->FindNestedElementWithName("IntRangeDomain");
    ASSERT_TRUE(range && range->GetAttribute("max")) << "no maximum";
    EXPECT_EQ(numbers(range->GetAttribute("max")).at(0), limit)
      << "the maximum is not Core's limit";
  }
}
