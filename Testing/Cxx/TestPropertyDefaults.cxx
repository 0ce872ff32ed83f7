// SPDX-License-Identifier: BSD-3-Clause
// The ServerManager XML and the VTK classes cannot disagree: every property
// the XML hands to a VTK setter (command="SetX") starts at the default the
// class itself starts with (GetX), read through the plugin's ClientServer
// wrapping, as ParaView calls the class; every enumeration's values are
// valid, distinct and its default among them. A property whose setter has no
// getter must be listed below with the reason. An enumeration's setter
// keeps each value the XML offers and none past them; where the class says
// its value as text (GetXAsString, vtkBPEnumMacro), each value set through
// SetX(int) reads back as the XML entry's text, and a fresh object's as the
// default entry's. A numeric setter keeps both ends of the range the XML's
// panel offers. An enumeration whose values are a Core enumeration's
// (Core/Choices/BoundParticlesChoices.h) offers exactly its values with its
// texts. Every property of the tracer is either held to Core's default (a
// new bpvtk::TracerConfig, whose bp::TraceSettings starts at
// bp::propertyDefaults()) or listed with why Core does not hold it. The test
// reads the XML where it is written (Plugin/), so that an edit is checked
// without a new build.
#include "vtkCallbackCommand.h"
#include "vtkClientServerInterpreter.h"
#include "vtkClientServerStream.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLUtilities.h"

#include "BoundParticlesChoices.h"
#include "EngineParameters.h"
#include "ReleaseLattice.h"
#include "TraceSettings.h"
#include "TracerConfig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

extern "C" void BoundParticlesFiltersCS_Initialize(vtkClientServerInterpreter*);
extern "C" void BoundParticlesIOCS_Initialize(vtkClientServerInterpreter*);
extern "C" void BoundParticlesRepresentationsCS_Initialize(vtkClientServerInterpreter*);

namespace
{
/// Setters with no getter to compare, and why.
const std::map<std::string, std::string> NoGetter = {
  { "SetInputConnection", "a pipeline connection, not a value" },
  { "SetInputArrayToProcess", "the array picked by the Vectors and Release Weights domains" },
  { "SetOutputArrayStatus", "a selection, defaulted from the output table (TestTracerOutput)" },
  { "SetSeedType", "a proxy, not a value" },
  { "SetFileName", "a file, no default" },
  { "SetFileNames", "files, no default" },
};

/// The display's setters that hand their value straight to its actor or
/// property, as ParaView's own geometry representation does: VTK's defaults
/// there, no getter on the representation.
const std::set<std::string> ForwardedByTheDisplay = { "SetVisibility", "SetMapScalars",
  "SetInterpolateScalarsBeforeMapping", "SetAmbientColor", "SetDiffuseColor", "SetSpecularColor",
  "SetOpacity", "SetAmbient", "SetDiffuse", "SetSpecular", "SetSpecularPower", "SetInterpolation",
  "SetPointSize", "SetLineWidth", "SetPosition", "SetScale", "SetOrientation", "SetOrigin",
  "SetUserTransform", "SetPickable" };

bool hasNoGetter(const std::string& className, const std::string& setter)
{
  return NoGetter.count(setter) ||
    (className == "vtkBoundParticleRepresentation" && ForwardedByTheDisplay.count(setter));
}

/// The Core enumeration's texts, value: text.
template <typename E>
std::map<int, std::string> coreTexts()
{
  std::map<int, std::string> texts;
  for (int v = 0; v < bp::enumCount<E>(); ++v)
  {
    texts[v] = bp::enumName(E(v));
  }
  return texts;
}

/// The enumerated properties whose values are a Core enumeration's
/// (Core/Choices/BoundParticlesChoices.h).
const std::map<std::string, std::map<int, std::string>> CoreChoices = {
  { "AnalyticFlow.Flow", coreTexts<bp::AnalyticFlow>() },
  { "BoundParticleTracer.ElementShape", coreTexts<bp::BuiltinShape>() },
  { "BoundParticleTracer.TemplateSprings", coreTexts<bp::MeshSprings>() },
  { "BoundParticleTracer.ReleaseOrientation", coreTexts<bp::Orientation>() },
  { "BoundParticleTracer.ReleasePattern", coreTexts<bp::ReleasePattern>() },
  { "BoundParticleTracer.Engine", coreTexts<bp::EngineChoice>() },
  { "BoundParticleTracer.StepSizeUnit", coreTexts<bp::StepUnit>() },
  { "BoundParticleTracer.ShapeMatchingMode", coreTexts<bp::ShapeFit>() },
  { "BoundParticleTracer.Integrator", coreTexts<bp::Integrator>() },
  { "BoundParticleTracer.Restoration", coreTexts<bp::Restoration>() },
  { "BoundParticleTracer.Anchor", coreTexts<bp::Anchor>() },
  { "BoundParticleTracer.Inertia", coreTexts<bp::Inertia>() },
  { "BoundParticleTracer.Linking", coreTexts<bp::Linking>() },
  { "BoundParticleTracer.ResetWhen", coreTexts<bp::ResetWhen>() },
};

/// The enumerated properties with no Core enumeration, and why.
const std::map<std::string, std::string> NoCoreChoice = {
  { "BoundParticleTracer.ColoringAxis", "an axis, 0 to 2 (a clamped int)" },
  { "BoundParticlesRepresentation.Interpolation", "vtkProperty's, handed to the actor" },
};
std::vector<double> numbers(const std::string& text)
{
  std::vector<double> values;
  std::istringstream in(text);
  for (double v; in >> v;)
  {
    values.push_back(v);
  }
  return values;
}

/// The numbers a getter's reply holds (one scalar or one array).
bool replyValues(const vtkClientServerStream& reply, std::vector<double>& values)
{
  if (reply.GetNumberOfMessages() != 1 || reply.GetCommand(0) != vtkClientServerStream::Reply ||
    reply.GetNumberOfArguments(0) != 1)
  {
    return false;
  }
  vtkTypeUInt32 length = 0;
  if (reply.GetArgumentLength(0, 0, &length) && length > 0)
  {
    values.resize(length);
    return reply.GetArgument(0, 0, values.data(), length) != 0;
  }
  double value = 0.0;
  bool flag = false;
  if (reply.GetArgument(0, 0, &value))
  {
    values = { value };
    return true;
  }
  if (reply.GetArgument(0, 0, &flag))
  {
    values = { flag ? 1.0 : 0.0 };
    return true;
  }
  return false;
}

/// The text a getter's reply holds.
bool replyString(const vtkClientServerStream& reply, std::string& text)
{
  const char* value = nullptr;
  if (reply.GetNumberOfMessages() != 1 || reply.GetCommand(0) != vtkClientServerStream::Reply ||
    reply.GetNumberOfArguments(0) != 1 || !reply.GetArgument(0, 0, &value) || !value)
  {
    return false;
  }
  text = value;
  return true;
}

class Classes
{
public:
  Classes()
  {
    BoundParticlesFiltersCS_Initialize(this->Interpreter);
    BoundParticlesIOCS_Initialize(this->Interpreter);
    BoundParticlesRepresentationsCS_Initialize(this->Interpreter);
  }

  /// A new object of the class, or 0 where the wrapping does not know it.
  vtkTypeUInt32 create(const std::string& className)
  {
    vtkClientServerStream s;
    const vtkClientServerID id(++this->LastId);
    s << vtkClientServerStream::New << className.c_str() << id << vtkClientServerStream::End;
    return this->Interpreter->ProcessStream(s) ? id.ID : 0;
  }

  /// What the object's getter returns, or false where it has none.
  bool get(vtkTypeUInt32 object, const std::string& getter, std::vector<double>& values)
  {
    vtkClientServerStream s;
    s << vtkClientServerStream::Invoke << vtkClientServerID(object) << getter.c_str()
      << vtkClientServerStream::End;
    return this->Interpreter->ProcessStream(s) &&
      replyValues(this->Interpreter->GetLastResult(), values);
  }

  /// What the object's text getter returns, or false where it has none.
  bool getString(vtkTypeUInt32 object, const std::string& getter, std::string& text)
  {
    vtkClientServerStream s;
    s << vtkClientServerStream::Invoke << vtkClientServerID(object) << getter.c_str()
      << vtkClientServerStream::End;
    return this->Interpreter->ProcessStream(s) &&
      replyString(this->Interpreter->GetLastResult(), text);
  }

  /// Calls the object's setter with one integer.
  template <typename T>
  bool set(vtkTypeUInt32 object, const std::string& setter, T value)
  {
    vtkClientServerStream s;
    s << vtkClientServerStream::Invoke << vtkClientServerID(object) << setter.c_str() << value
      << vtkClientServerStream::End;
    return this->Interpreter->ProcessStream(s) != 0;
  }

  /// Whether the plugin's wrapping makes objects of the class.
  bool knows(const std::string& className)
  {
    vtkObjectBase* object = this->Interpreter->NewInstance(className.c_str());
    if (object)
    {
      object->Delete();
    }
    return object != nullptr;
  }

  /// The object the interpreter holds under `id`.
  vtkObject* object(vtkTypeUInt32 id)
  {
    return vtkObject::SafeDownCast(this->Interpreter->GetObjectFromID(vtkClientServerID(id), 1));
  }

private:
  vtkNew<vtkClientServerInterpreter> Interpreter;
  vtkTypeUInt32 LastId = 100;
};

/// Each proxy of the XML file whose class the plugin wraps.
std::vector<vtkXMLDataElement*> proxies(vtkXMLDataElement* root, Classes& classes)
{
  std::vector<vtkXMLDataElement*> found;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement* proxy = group->GetNestedElement(p);
      const char* className = proxy->GetAttribute("class");
      if (className && classes.knows(className))
      {
        found.push_back(proxy);
      }
    }
  }
  return found;
}

bool isValueProperty(vtkXMLDataElement* property)
{
  const std::string tag = property->GetName();
  return (tag == "IntVectorProperty" || tag == "DoubleVectorProperty" ||
           tag == "IdTypeVectorProperty") &&
    property->GetAttribute("command") && property->GetAttribute("default_values") &&
    !property->GetAttribute("information_only");
}

vtkXMLDataElement* enumeration(vtkXMLDataElement* property)
{
  return property->FindNestedElementWithName("EnumerationDomain");
}

/// The entries of an enumeration, value: text.
std::map<int, std::string> entriesOf(vtkXMLDataElement* domain)
{
  std::map<int, std::string> entries;
  for (int k = 0; k < domain->GetNumberOfNestedElements(); ++k)
  {
    int value = -1;
    domain->GetNestedElement(k)->GetScalarAttribute("value", value);
    const char* text = domain->GetNestedElement(k)->GetAttribute("text");
    entries[value] = text ? text : "";
  }
  return entries;
}

/// Whether the class says the property's value as text (vtkBPEnumMacro's
/// GetXAsString).
bool saysAsText(Classes& classes, const std::string& className, const std::string& setter)
{
  std::string text;
  return classes.getString(classes.create(className), "Get" + setter.substr(3) + "AsString", text);
}

/// The class keeps every value the XML offers, and no value past them (its
/// setter clamps or refuses, with a warning). Where it says its value as
/// text, each value set reads back as the entry's text, and one past the
/// last as the last's (clamped).
void checkEnumeration(Classes& classes, const std::string& className, const std::string& setter,
  const std::map<int, std::string>& offered)
{
  const vtkTypeUInt32 object = classes.create(className);
  const bool asText = saysAsText(classes, className, setter);
  const std::string getter = "Get" + setter.substr(3) + (asText ? "AsString" : "");
  // The object's warnings are counted (and not shown).
  int warned = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&warned);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  ASSERT_TRUE(classes.object(object));
  classes.object(object)->AddObserver(vtkCommand::WarningEvent, counter);
  const int first = offered.begin()->first, last = offered.rbegin()->first;
  std::vector<int> tried;
  for (const auto& entry : offered)
  {
    tried.push_back(entry.first);
  }
  tried.push_back(last + 1);
  if (asText)
  {
    tried.push_back(first - 1);
  }
  for (int value : tried)
  {
    warned = 0;
    ASSERT_TRUE(classes.set(object, setter, value)) << setter << "(" << value << ")";
    if (asText)
    {
      EXPECT_EQ(warned, offered.count(value) ? 0 : 1)
        << setter << "(" << value << "): a number that names no value is said, once";
      std::string text;
      ASSERT_TRUE(classes.getString(object, getter, text)) << getter;
      const std::string expected = offered.at(std::max(first, std::min(value, last)));
      EXPECT_EQ(text, expected) << setter << "(" << value << ") then " << getter
                                << ": the XML's entry is \"" << expected << "\"";
      continue;
    }
    std::vector<double> kept;
    ASSERT_TRUE(classes.get(object, getter, kept));
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0] == value, offered.count(value) == 1)
      << setter << "(" << value << ") keeps " << kept[0] << ": the XML offers "
      << (offered.count(value) ? "it" : "no such value");
  }
}

/// The class keeps the ends of the range the XML's panel offers (a setter
/// that clamps tighter would take a value the panel shows away from it).
void checkRange(Classes& classes, const std::string& className, vtkXMLDataElement* property)
{
  vtkXMLDataElement* range = property->FindNestedElementWithName("IntRangeDomain");
  const bool integer = range != nullptr;
  range = range ? range : property->FindNestedElementWithName("DoubleRangeDomain");
  const char* elements = property->GetAttribute("number_of_elements");
  if (!range || !elements || std::string(elements) != "1")
  {
    return;
  }
  const std::string setter = property->GetAttribute("command");
  const std::string getter = "Get" + setter.substr(3);
  for (const char* end : { "min", "max" })
  {
    const char* text = range->GetAttribute(end);
    if (!text)
    {
      continue;
    }
    const double value = numbers(text).at(0);
    const vtkTypeUInt32 object = classes.create(className);
    const bool sent =
      integer ? classes.set(object, setter, int(value)) : classes.set(object, setter, value);
    std::vector<double> kept;
    ASSERT_TRUE(sent && classes.get(object, getter, kept));
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0], value) << "the range's " << end << " " << value << " becomes " << kept[0];
  }
}

void checkFile(const std::string& path)
{
  SCOPED_TRACE(path);
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
  ASSERT_TRUE(root) << "cannot read " << path;
  // One interpreter for the process: the wrapping registers its classes
  // with the first interpreter it is given, once.
  static Classes classes;
  int compared = 0;
  for (vtkXMLDataElement* proxy : proxies(root, classes))
  {
    const std::string className = proxy->GetAttribute("class");
    const vtkTypeUInt32 object = classes.create(className);
    ASSERT_NE(object, 0u) << className;
    for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* property = proxy->GetNestedElement(i);
      if (!isValueProperty(property))
      {
        continue;
      }
      const std::string name = property->GetAttribute("name");
      const std::string setter = property->GetAttribute("command");
      SCOPED_TRACE(className + "." + name);
      const std::vector<double> declared = numbers(property->GetAttribute("default_values"));
      if (vtkXMLDataElement* entries = enumeration(property))
      {
        std::set<double> values;
        for (int e = 0; e < entries->GetNumberOfNestedElements(); ++e)
        {
          double value = 0.0;
          ASSERT_TRUE(entries->GetNestedElement(e)->GetScalarAttribute("value", value));
          EXPECT_TRUE(values.insert(value).second) << "value " << value << " twice";
        }
        EXPECT_TRUE(values.count(declared.at(0))) << "default not an entry";
        if (!hasNoGetter(className, setter))
        {
          const std::map<int, std::string> offered = entriesOf(entries);
          const std::string key = std::string(proxy->GetAttribute("name")) + "." + name;
          const bool asText = saysAsText(classes, className, setter);
          EXPECT_TRUE(asText || NoCoreChoice.count(key))
            << className << " has no Get" << setter.substr(3)
            << "AsString: a property of a Core enumeration is declared with vtkBPEnumMacro";
          checkEnumeration(classes, className, setter, offered);
          if (asText)
          {
            // The typed getter is C++ only: the default is compared as text.
            std::string text;
            ASSERT_TRUE(classes.getString(object, "Get" + setter.substr(3) + "AsString", text));
            EXPECT_EQ(text, offered.at(int(declared.at(0))))
              << "the XML's default is \"" << offered.at(int(declared.at(0)))
              << "\", the class starts at \"" << text << "\"";
            ++compared;
            continue;
          }
        }
      }
      if (hasNoGetter(className, setter))
      {
        continue;
      }
      checkRange(classes, className, property);
      ASSERT_EQ(setter.rfind("Set", 0), 0u) << "command " << setter;
      std::vector<double> actual;
      ASSERT_TRUE(classes.get(object, "Get" + setter.substr(3), actual))
        << className << " has no Get" << setter.substr(3)
        << " (add one, or list the setter in NoGetter with why)";
      ASSERT_EQ(actual.size(), declared.size());
      for (std::size_t k = 0; k < actual.size(); ++k)
      {
        EXPECT_NEAR(actual[k], declared[k], 1e-12 * std::max(1.0, std::abs(declared[k])))
          << "component " << k << ": the XML says " << declared[k] << ", the class starts at "
          << actual[k];
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 0) << "no property compared";
  std::printf("%s: %d defaults compared\n", path.c_str(), compared);
}

/// Each enumerated property of the XML, "Proxy.Property": the entries it
/// offers, value: text.
std::map<std::string, std::map<int, std::string>> enumerations(const std::string& path)
{
  std::map<std::string, std::map<int, std::string>> found;
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
  for (int g = 0; root && g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement* proxy = group->GetNestedElement(p);
      for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
      {
        vtkXMLDataElement* property = proxy->GetNestedElement(i);
        vtkXMLDataElement* domain = enumeration(property);
        if (!domain || !proxy->GetAttribute("name") || !property->GetAttribute("name"))
        {
          continue;
        }
        found[std::string(proxy->GetAttribute("name")) + "." + property->GetAttribute("name")] =
          entriesOf(domain);
      }
    }
  }
  return found;
}

} // namespace

TEST(PropertyDefaults, TheXmlNamesEveryChoiceAsCoreDoes)
{
  const auto inXml = enumerations(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
  for (const auto& [property, entries] : inXml)
  {
    SCOPED_TRACE(property);
    const auto core = CoreChoices.find(property);
    if (core == CoreChoices.end())
    {
      EXPECT_TRUE(NoCoreChoice.count(property))
        << "an enumeration with no Core enumeration: add its enum to BoundParticlesChoices.h "
           "and it to CoreChoices, or it to NoCoreChoice with why";
      continue;
    }
    EXPECT_EQ(entries, core->second)
      << "the XML's entries (value: text) are not the Core enumeration's texts";
  }
  for (const auto& [property, texts] : CoreChoices)
  {
    EXPECT_TRUE(inXml.count(property)) << property << " is no enumeration of the XML";
  }
  for (const auto& [property, why] : NoCoreChoice)
  {
    EXPECT_TRUE(inXml.count(property)) << property << " is no enumeration of the XML";
  }
}

namespace
{
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
  { "MinimumReleaseSpeed", [](const auto& c) { return one(c.trace.minimumReleaseSpeed); } },
  { "Trails", [](const auto& c) { return one(c.trace.trailLength > 0 ? 1 : 0); } },
  { "TrailSpacing", [](const auto& c) { return one(c.trace.trailSpacing); } },
  { "LifetimeRange", [](const auto& c) { return all(c.trace.lifetimeRange); } },
  { "Seed", [](const auto& c) { return one(c.trace.engine.seed); } },
  { "ColoringAxis", [](const auto& c) { return one(c.coloringAxis); } },
  { "CheckpointMemory", [](const auto& c) { return one(c.checkpointMemory); } },
};

/// The tracer's properties Core does not hold as the panel does, and why.
const std::map<std::string, std::string> NotInCore = {
  { "Input", "an input" },
  { "ElementTemplate", "an input (TracerConfig::templateInput says whether it is connected)" },
  { "SeedSource", "an input (TracerConfig::seedSource says whether it is connected)" },
  { "Vectors", "an array of the input, chosen by its domain" },
  { "ReleaseWeights", "an array of the input, chosen by its domain" },
  { "UnitsMismatchedVectors", "information, from the input" },
  { "UnitsFittingVectors", "information, from the input" },
  { "SeedType", "a proxy (TracerConfig::seedType, none by default)" },
  { "EmitterBoxUseReferenceBounds", "the box widget's, no command" },
  { "EmitterBoxReferenceBounds", "the box widget's, no command" },
  { "Duration", "the time line's, read in RequestInformation" },
  { "NumberOfTimeSteps", "the time line's, read in RequestInformation" },
  { "FramesPerInputStep", "the time line's, read in RequestInformation" },
  { "ReleaseWindow", "Core holds the window's ends, infinite while it is off" },
  { "ReleaseStart", "Core holds -infinity while Release Window is off" },
  { "ReleaseStop", "Core holds +infinity while Release Window is off" },
  { "TrailLength", "Core holds 0 while Trails is off" },
  { "OutputArrayInfo", "information, the table of bp::outputArrays()" },
  { "OutputArrays", "a selection, defaulted from the output table (TestTracerOutput)" },
  { "ComputeVorticity", "folded into TracerConfig::wanted (Vorticity)" },
  { "ResolvedTimeStep", "information, what the last update resolved" },
  { "ResolvedElementSize", "information, what the last update resolved" },
  { "SimulationTime", "information, what the last update did" },
  { "StepsInLastUpdate", "information, what the last update did" },
  { "LastUpdateReplayed", "information, what the last update did" },
  { "CheckpointSpacing", "information, what the last update did" },
  { "TimestepValues", "information, the time line" },
  { "TimeRange", "information, the time line" },
};
} // namespace

TEST(PropertyDefaults, TheTracersDefaultsAreCores)
{
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(
    vtkXMLUtilities::ReadElementFromFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml"));
  ASSERT_TRUE(root);
  vtkXMLDataElement* tracer = nullptr;
  for (int g = 0; !tracer && g < root->GetNumberOfNestedElements(); ++g)
  {
    tracer = root->GetNestedElement(g)->FindNestedElementWithNameAndAttribute(
      "BoundParticleTracerProxy", "name", "BoundParticleTracer");
  }
  ASSERT_TRUE(tracer) << "no BoundParticleTracer proxy";
  const bpvtk::TracerConfig fresh;
  int compared = 0, exempt = 0;
  std::set<std::string> seen;
  for (int i = 0; i < tracer->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* property = tracer->GetNestedElement(i);
    const std::string tag = property->GetName();
    if (tag.size() < 8 || tag.compare(tag.size() - 8, 8, "Property") != 0)
    {
      continue;
    }
    const std::string name = property->GetAttribute("name");
    SCOPED_TRACE(name);
    seen.insert(name);
    const auto field = CoreDefaults.find(name);
    if (field == CoreDefaults.end())
    {
      EXPECT_TRUE(NotInCore.count(name))
        << "a property with no verdict: add its Core field to CoreDefaults, or it to NotInCore "
           "with why";
      ++exempt;
      continue;
    }
    EXPECT_FALSE(NotInCore.count(name)) << "both in CoreDefaults and NotInCore";
    const char* text = property->GetAttribute("default_values");
    ASSERT_TRUE(text) << "no default";
    const std::vector<double> declared = numbers(text);
    const std::vector<double> core = field->second(fresh);
    ASSERT_EQ(core.size(), declared.size());
    for (std::size_t k = 0; k < core.size(); ++k)
    {
      // Core holds many of them as float.
      EXPECT_NEAR(core[k], declared[k], 1e-6 * std::max(1.0, std::abs(declared[k])))
        << "component " << k << ": the panel starts at " << declared[k] << ", Core at " << core[k];
    }
    ++compared;
  }
  for (const auto& [name, core] : CoreDefaults)
  {
    EXPECT_TRUE(seen.count(name)) << name << " is no property of the tracer";
  }
  for (const auto& [name, why] : NotInCore)
  {
    EXPECT_TRUE(seen.count(name)) << name << " is no property of the tracer";
  }
  std::printf("%zu properties of the tracer: %d against Core, %d not in Core\n", seen.size(),
    compared, exempt);
}

TEST(PropertyDefaults, TheXmlAndTheFiltersAgree)
{
  checkFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
}

TEST(PropertyDefaults, TheXmlAndTheReadersAgree)
{
  checkFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticlesReaders.xml");
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
} // namespace

TEST(PropertyDefaults, EveryDecoratorNamesAValueItsPropertyTakes)
{
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(
    vtkXMLUtilities::ReadElementFromFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml"));
  ASSERT_TRUE(root);
  int checked = 0;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement* proxy = group->GetNestedElement(p);
      std::vector<vtkXMLDataElement*> decorators;
      genericDecorators(proxy, decorators);
      for (vtkXMLDataElement* decorator : decorators)
      {
        const char* name = decorator->GetAttribute("property");
        ASSERT_TRUE(name) << "a GenericDecorator without its property";
        SCOPED_TRACE(std::string(proxy->GetAttribute("name")) + ": decorator on " + name);
        vtkXMLDataElement* property =
          proxy->FindNestedElementWithNameAndAttribute("IntVectorProperty", "name", name);
        ASSERT_TRUE(property) << "no IntVectorProperty " << name << " in the proxy";
        std::set<int> taken;
        if (vtkXMLDataElement* domain = enumeration(property))
        {
          for (const auto& entry : entriesOf(domain))
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
  }
  EXPECT_GT(checked, 0);
  std::printf("%d decorators checked\n", checked);
}

TEST(PropertyDefaults, TheDisplaysInterpolationIsVtkPropertys)
{
  // The display hands Interpolation to its actor's vtkProperty: the XML's
  // entries are vtkProperty's values and texts.
  const auto inXml = enumerations(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml");
  const auto entries = inXml.find("BoundParticlesRepresentation.Interpolation");
  ASSERT_NE(entries, inXml.end());
  vtkNew<vtkProperty> property;
  for (const auto& [value, text] : entries->second)
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
  const std::map<std::string, double> limits = {
    { "BoundParticleTracer.TrailLength", bp::MaxTrailLength },
    { "BoundParticleTracer.TrailSpacing", bp::MaxTrailSpacing },
    { "BoundParticleTracer.FramesPerInputStep", bp::MaxFramesPerInterval },
    { "BoundParticleTracer.NumberOfElements", bp::MaxLatticeCount },
    { "PointCloud.NumberOfPoints", double(bp::MaxSeedPoints) },
  };
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(
    vtkXMLUtilities::ReadElementFromFile(BOUNDPARTICLES_PLUGIN_XML_DIR "/BoundParticles.xml"));
  ASSERT_TRUE(root);
  std::set<std::string> found;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement* proxy = group->GetNestedElement(p);
      for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
      {
        vtkXMLDataElement* property = proxy->GetNestedElement(i);
        const char* proxyName = proxy->GetAttribute("name");
        const char* name = property->GetAttribute("name");
        if (!proxyName || !name || !limits.count(std::string(proxyName) + "." + name))
        {
          continue;
        }
        const std::string key = std::string(proxyName) + "." + name;
        vtkXMLDataElement* range = property->FindNestedElementWithName("IntRangeDomain");
        ASSERT_TRUE(range && range->GetAttribute("max")) << key << " has no maximum";
        EXPECT_EQ(numbers(range->GetAttribute("max")).at(0), limits.at(key))
          << key << "'s maximum is not Core's limit";
        found.insert(key);
      }
    }
  }
  EXPECT_EQ(found.size(), limits.size()) << "a property of the table is not in the XML";
}
