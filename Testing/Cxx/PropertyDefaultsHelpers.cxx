// SPDX-License-Identifier: BSD-3-Clause
#include "PropertyDefaultsHelpers.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkClientServerStream.h"
#include "vtkCommand.h"
#include "vtkLinearTransform.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProperty.h"
#include "vtkVersion.h"
#include "vtkXMLUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

extern "C" void BoundParticlesFiltersCS_Initialize(vtkClientServerInterpreter*);
extern "C" void BoundParticlesIOCS_Initialize(vtkClientServerInterpreter*);
extern "C" void BoundParticlesRepresentationsCS_Initialize(vtkClientServerInterpreter*);

namespace pdt
{
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

namespace
{
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

/// The vtkActors and vtkPropertys made while it is registered (and enabled),
/// in order. It makes them as VTK would without it; its overrides are the
/// only ones enabled for those two classes while it is.
class CatchingFactory : public vtkObjectFactory
{
public:
  static CatchingFactory* New()
  {
    auto* factory = new CatchingFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  vtkTypeMacro(CatchingFactory, vtkObjectFactory);
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "TestPropertyDefaults' catching factory"; }

  static std::vector<vtkObject*>& caught()
  {
    static std::vector<vtkObject*> objects;
    return objects;
  }

private:
  CatchingFactory()
  {
    this->RegisterOverride(
      "vtkActor", "CaughtActor", "caught", 1, &CatchingFactory::make<vtkActor>);
    this->RegisterOverride(
      "vtkProperty", "CaughtProperty", "caught", 1, &CatchingFactory::make<vtkProperty>);
  }

  /// The object VTK makes when no factory answers (this one answers nothing
  /// while it makes it).
  template <typename T>
  static vtkObject* make()
  {
    static bool inside = false;
    if (inside)
    {
      return nullptr;
    }
    inside = true;
    T* object = T::New();
    inside = false;
    caught().push_back(object);
    return object;
  }
};
} // namespace

/// The display's setters that hand their value straight to its actor, the
/// actor's vtkProperty or its CPU mapper (Representations/
/// vtkBoundParticleRepresentation.cxx), as ParaView's own geometry
/// representation does: the value read back from there.
template <typename T>
std::vector<double> three(const T* v)
{
  return { double(v[0]), double(v[1]), double(v[2]) };
}
const std::map<std::string, DisplayGetter>& displayGetters()
{
  static const std::map<std::string, DisplayGetter> getters = {
    { "SetVisibility",
      [](const auto& d) { return std::vector<double>{ double(d.Actor->GetVisibility()) }; } },
    { "SetMapScalars",
      [](const auto& d)
      {
        // SetMapScalars(v) sets the colour mode to map (v) or direct (!v)
        // scalars; VTK's default mode is neither.
        const int mode = d.Mapper->GetColorMode();
        return std::vector<double>{ mode == VTK_COLOR_MODE_MAP_SCALARS ? 1.0
            : mode == VTK_COLOR_MODE_DIRECT_SCALARS                    ? 0.0
                                                                       : -1.0 };
      } },
    { "SetInterpolateScalarsBeforeMapping",
      [](const auto& d)
      { return std::vector<double>{ double(d.Mapper->GetInterpolateScalarsBeforeMapping()) }; } },
    { "SetAmbientColor", [](const auto& d) { return three(d.Property->GetAmbientColor()); } },
    { "SetDiffuseColor", [](const auto& d) { return three(d.Property->GetDiffuseColor()); } },
    { "SetSpecularColor", [](const auto& d) { return three(d.Property->GetSpecularColor()); } },
    { "SetOpacity", [](const auto& d) { return std::vector<double>{ d.Property->GetOpacity() }; } },
    { "SetAmbient", [](const auto& d) { return std::vector<double>{ d.Property->GetAmbient() }; } },
    { "SetDiffuse", [](const auto& d) { return std::vector<double>{ d.Property->GetDiffuse() }; } },
    { "SetSpecular",
      [](const auto& d) { return std::vector<double>{ d.Property->GetSpecular() }; } },
    { "SetSpecularPower",
      [](const auto& d) { return std::vector<double>{ d.Property->GetSpecularPower() }; } },
    { "SetInterpolation",
      [](const auto& d) { return std::vector<double>{ double(d.Property->GetInterpolation()) }; } },
    { "SetPointSize",
      [](const auto& d) { return std::vector<double>{ double(d.Property->GetPointSize()) }; } },
    { "SetLineWidth",
      [](const auto& d) { return std::vector<double>{ double(d.Property->GetLineWidth()) }; } },
    { "SetPosition", [](const auto& d) { return three(d.Actor->GetPosition()); } },
    { "SetScale", [](const auto& d) { return three(d.Actor->GetScale()); } },
    { "SetOrientation", [](const auto& d) { return three(d.Actor->GetOrientation()); } },
    { "SetOrigin", [](const auto& d) { return three(d.Actor->GetOrigin()); } },
    { "SetUserTransform",
      [](const auto& d)
      {
        // No user transform is the identity.
        vtkNew<vtkMatrix4x4> matrix;
        if (vtkLinearTransform* transform = d.Actor->GetUserTransform())
        {
          matrix->DeepCopy(transform->GetMatrix());
        }
        return std::vector<double>(matrix->GetData(), matrix->GetData() + 16);
      } },
    { "SetPickable",
      [](const auto& d) { return std::vector<double>{ double(d.Actor->GetPickable()) }; } },
  };
  return getters;
}

Classes::Classes()
{
  BoundParticlesFiltersCS_Initialize(this->Interpreter);
  BoundParticlesIOCS_Initialize(this->Interpreter);
  BoundParticlesRepresentationsCS_Initialize(this->Interpreter);
}

Classes& classes()
{
  static Classes instance;
  return instance;
}

vtkTypeUInt32 Classes::create(const std::string& className, DisplayObjects* display)
{
  vtkNew<CatchingFactory> factory;
  CatchingFactory::caught().clear();
  if (display)
  {
    vtkObjectFactory::SetAllEnableFlags(0, "vtkActor");
    vtkObjectFactory::SetAllEnableFlags(0, "vtkProperty");
    vtkObjectFactory::RegisterFactory(factory);
    factory->SetEnableFlag(1, "vtkActor", "CaughtActor");
    factory->SetEnableFlag(1, "vtkProperty", "CaughtProperty");
  }
  vtkClientServerStream s;
  const vtkClientServerID id(++this->LastId);
  s << vtkClientServerStream::New << className.c_str() << id << vtkClientServerStream::End;
  const bool made = this->Interpreter->ProcessStream(s) != 0;
  if (display)
  {
    vtkObjectFactory::UnRegisterFactory(factory);
    vtkObjectFactory::SetAllEnableFlags(1, "vtkActor");
    vtkObjectFactory::SetAllEnableFlags(1, "vtkProperty");
    for (vtkObject* object : CatchingFactory::caught())
    {
      if (!display->Actor && vtkActor::SafeDownCast(object))
      {
        display->Actor = vtkActor::SafeDownCast(object);
      }
      else if (!display->Property && vtkProperty::SafeDownCast(object))
      {
        display->Property = vtkProperty::SafeDownCast(object);
      }
    }
    display->Mapper = display->Actor ? display->Actor->GetMapper() : nullptr;
    CatchingFactory::caught().clear();
  }
  return made ? id.ID : 0;
}

bool Classes::get(vtkTypeUInt32 object, const std::string& getter, std::vector<double>& values)
{
  vtkClientServerStream s;
  s << vtkClientServerStream::Invoke << vtkClientServerID(object) << getter.c_str()
    << vtkClientServerStream::End;
  return this->Interpreter->ProcessStream(s) &&
    replyValues(this->Interpreter->GetLastResult(), values);
}

bool Classes::getString(vtkTypeUInt32 object, const std::string& getter, std::string& text)
{
  vtkClientServerStream s;
  s << vtkClientServerStream::Invoke << vtkClientServerID(object) << getter.c_str()
    << vtkClientServerStream::End;
  if (!this->Interpreter->ProcessStream(s))
  {
    return false;
  }
  const vtkClientServerStream& reply = this->Interpreter->GetLastResult();
  if (reply.GetNumberOfMessages() != 1 || reply.GetCommand(0) != vtkClientServerStream::Reply)
  {
    return false;
  }
  if (reply.GetNumberOfArguments(0) == 0)
  {
    text.clear(); // a null const char*
    return true;
  }
  const char* value = nullptr;
  if (reply.GetNumberOfArguments(0) != 1 || !reply.GetArgument(0, 0, &value))
  {
    return false;
  }
  text = value ? value : "";
  return true;
}

bool Classes::set(
  vtkTypeUInt32 object, const std::string& setter, const std::vector<double>& values, bool asInt)
{
  vtkClientServerStream s;
  s << vtkClientServerStream::Invoke << vtkClientServerID(object) << setter.c_str();
  for (double value : values)
  {
    if (asInt)
    {
      s << int(value);
    }
    else
    {
      s << value;
    }
  }
  s << vtkClientServerStream::End;
  return this->Interpreter->ProcessStream(s) != 0;
}

bool Classes::knows(const std::string& className)
{
  vtkObjectBase* object = this->Interpreter->NewInstance(className.c_str());
  if (object)
  {
    object->Delete();
  }
  return object != nullptr;
}

vtkObject* Classes::object(vtkTypeUInt32 id)
{
  return vtkObject::SafeDownCast(this->Interpreter->GetObjectFromID(vtkClientServerID(id), 1));
}

XmlFile readXml(const std::string& path)
{
  XmlFile file;
  file.Root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
  for (int g = 0; file.Root && g < file.Root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = file.Root->GetNestedElement(g);
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement* element = group->GetNestedElement(p);
      const char* groupName = group->GetAttribute("name");
      const char* name = element->GetAttribute("name");
      const char* className = element->GetAttribute("class");
      file.Proxies.push_back(
        { groupName ? groupName : "", name ? name : "", className ? className : "", element });
    }
  }
  return file;
}

bool isProperty(vtkXMLDataElement* element)
{
  const std::string tag = element->GetName();
  return tag.size() > 8 && tag.compare(tag.size() - 8, 8, "Property") == 0;
}

vtkXMLDataElement* enumeration(vtkXMLDataElement* property)
{
  return property->FindNestedElementWithName("EnumerationDomain");
}

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

/// The entries' values are distinct and the default is one of them.
void checkEntries(const std::string& key, vtkXMLDataElement* domain, double declared)
{
  std::set<double> values;
  for (int e = 0; e < domain->GetNumberOfNestedElements(); ++e)
  {
    double value = 0.0;
    ASSERT_TRUE(domain->GetNestedElement(e)->GetScalarAttribute("value", value));
    EXPECT_TRUE(values.insert(value).second) << key << ": value " << value << " twice";
  }
  EXPECT_TRUE(values.count(declared)) << key << ": the default " << declared << " is no entry";
}

/// The class keeps every value the XML offers, and no value past them (its
/// setter clamps or refuses, with a warning). Where it says its value as
/// text, each value set reads back as the entry's text, and one past either
/// end as that end's (clamped).
void checkEnumeration(const std::string& key, vtkTypeUInt32 object, const std::string& setter,
  const std::map<int, std::string>& offered, bool asText)
{
  Classes& classes = pdt::classes();
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
    ASSERT_TRUE(classes.set(object, setter, { double(value) }, true))
      << setter << "(" << value << ")";
    if (asText)
    {
      EXPECT_EQ(warned, offered.count(value) ? 0 : 1)
        << key << ": " << setter << "(" << value << "): a number that names no value is said, once";
      std::string text;
      ASSERT_TRUE(classes.getString(object, getter, text)) << getter;
      const std::string expected = offered.at(std::max(first, std::min(value, last)));
      EXPECT_EQ(text, expected) << key << ": " << setter << "(" << value << ") then " << getter
                                << ": the XML's entry is \"" << expected << "\"";
      continue;
    }
    std::vector<double> kept;
    ASSERT_TRUE(classes.get(object, getter, kept));
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0] == value, offered.count(value) == 1)
      << key << ": " << setter << "(" << value << ") keeps " << kept[0] << ": the XML offers "
      << (offered.count(value) ? "it" : "no such value");
  }
}

/// An enumeration's entries, value and text, are its Core enumeration's.
void checkCoreEntries(const std::string& key, const std::map<int, std::string>& inXml,
  const std::map<int, std::string>& core)
{
  for (const auto& [value, text] : inXml)
  {
    const auto said = core.find(value);
    EXPECT_TRUE(said != core.end() && said->second == text)
      << key << ": the XML's entry " << value << " \"" << text << "\" is "
      << (said == core.end() ? "no value of the Core enumeration"
                             : "\"" + said->second + "\" in Core");
  }
  for (const auto& [value, text] : core)
  {
    EXPECT_TRUE(inXml.count(value)) << key << ": the Core enumeration's " << value << " \"" << text
                                    << "\" is no entry of the XML";
  }
}
} // namespace pdt
