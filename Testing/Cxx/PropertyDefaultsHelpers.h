// SPDX-License-Identifier: BSD-3-Clause
// TestPropertyDefaults' means: the plugin's classes called through their
// ClientServer wrapping, as ParaView calls them; the objects a new Bound
// Particles display forwards its setters to; and the proxy XML read.
#ifndef PropertyDefaultsHelpers_h
#define PropertyDefaultsHelpers_h

#include "vtkActor.h" // for DisplayObjects
#include "vtkClientServerInterpreter.h"
#include "vtkNew.h"
#include "vtkProperty.h" // for DisplayObjects
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

class vtkMapper;
class vtkObject;

namespace pdt
{
/// The numbers of a text ("1 0.5 -1" holds three).
std::vector<double> numbers(const std::string& text);

/// The objects a new vtkBoundParticleRepresentation draws with, which its
/// setters of colour, lighting, size and transform hand their values to:
/// its actor, the actor's vtkProperty and its CPU mapper. The representation
/// has no getters for them; they are caught as VTK's object factory makes
/// them (the first vtkActor and vtkProperty made while it is made).
struct DisplayObjects
{
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkProperty> Property;
  vtkMapper* Mapper = nullptr; // the actor's
};

/// The display's setters that hand their value straight to its actor, the
/// actor's vtkProperty or its CPU mapper (Representations/
/// vtkBoundParticleRepresentation.cxx), as ParaView's own geometry
/// representation does, each with the getter that reads the value back there.
using DisplayGetter = std::function<std::vector<double>(const DisplayObjects&)>;
const std::map<std::string, DisplayGetter>& displayGetters();

/// One interpreter for the process: the wrapping registers its classes with
/// the first interpreter it is given, once.
class Classes
{
public:
  Classes();

  /// A new object of the class, or 0 where the wrapping does not know it.
  /// Where the class makes a vtkActor and a vtkProperty (the display),
  /// `display` gets them.
  vtkTypeUInt32 create(const std::string& className, DisplayObjects* display = nullptr);

  /// What the object's getter returns (one scalar or one array), or false
  /// where it has none.
  bool get(vtkTypeUInt32 object, const std::string& getter, std::vector<double>& values);

  /// What the object's text getter returns ("" for a null pointer), or false
  /// where it has none.
  bool getString(vtkTypeUInt32 object, const std::string& getter, std::string& text);

  /// Calls the object's setter with the values, as ints or as doubles.
  bool set(
    vtkTypeUInt32 object, const std::string& setter, const std::vector<double>& values, bool asInt);

  /// Whether the plugin's wrapping makes objects of the class.
  bool knows(const std::string& className);

  /// The object the interpreter holds under `id`.
  vtkObject* object(vtkTypeUInt32 id);

private:
  vtkNew<vtkClientServerInterpreter> Interpreter;
  vtkTypeUInt32 LastId = 100;
};

Classes& classes();

/// A proxy of the XML: its group's and its own name, its class, its element.
struct Proxy
{
  std::string Group;
  std::string Name;
  std::string ClassName; // empty for a proxy with no class (NullProxy, Extension)
  vtkXMLDataElement* Element = nullptr;
};

/// The XML file read, and each proxy of each of its groups.
struct XmlFile
{
  vtkSmartPointer<vtkXMLDataElement> Root;
  std::vector<Proxy> Proxies;
};
XmlFile readXml(const std::string& path);

/// Whether the element is a property (its tag ends in "Property").
bool isProperty(vtkXMLDataElement* element);

/// The property's EnumerationDomain, or null.
vtkXMLDataElement* enumeration(vtkXMLDataElement* property);

/// The entries of an enumeration, value: text.
std::map<int, std::string> entriesOf(vtkXMLDataElement* domain);

/// The enumeration's values are distinct and the default is one of them.
void checkEntries(const std::string& key, vtkXMLDataElement* domain, double declared);

/// The class (a fresh `object`) keeps every value the XML offers, and no
/// value past them (its setter clamps or refuses, with a warning). Where it
/// says its value as text (`asText`: GetXAsString, vtkBPEnumMacro), each
/// value set reads back as the entry's text, and one past either end as that
/// end's (clamped).
void checkEnumeration(const std::string& key, vtkTypeUInt32 object, const std::string& setter,
  const std::map<int, std::string>& offered, bool asText);

/// The XML's entries, value and text, are the Core enumeration's.
void checkCoreEntries(const std::string& key, const std::map<int, std::string>& inXml,
  const std::map<int, std::string>& core);
} // namespace pdt

#endif
