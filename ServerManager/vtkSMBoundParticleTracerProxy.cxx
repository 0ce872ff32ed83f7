// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBoundParticleTracerProxy.h"

#include "vtkObjectFactory.h"
#include "vtkPVXMLElement.h"
#include "vtkSMDoubleVectorProperty.h"
#include "vtkSMEnumerationDomain.h"
#include "vtkSMIdTypeVectorProperty.h"
#include "vtkSMIntVectorProperty.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSMBoundParticleTracerProxy);

namespace
{
/// Whether ParaView's state loading reads `text` as a T: it reads a state
/// value with a stream (vtkSMVectorPropertyTemplate), and where the stream
/// fails the value is 0.
template <class T>
bool streamReads(const char* text)
{
  std::istringstream in(text);
  T value;
  in >> value;
  return !in.fail();
}

/// `text` as a whole as a double (strtod: also "nan", "inf", "Infinity",
/// and +-infinity beyond double's range); false where it is not a number.
bool wholeNumber(const std::string& text, double& value)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if (end == begin)
  {
    return false;
  }
  while (*end != '\0' && std::isspace(static_cast<unsigned char>(*end)))
  {
    ++end;
  }
  return *end == '\0';
}

/// A value of the state that ParaView's loading reads as 0.
struct Unread
{
  std::string property;
  unsigned int index = 0;
  std::string text;
  bool held = false;   ///< the property had an element there before loading
  double before = 0.0; ///< the element's value before loading (its default)
  long long beforeInteger = 0;
};

/// The property's element `index` before loading, where it has one.
void holdBefore(vtkSMProperty* property, Unread& u)
{
  if (auto* d = vtkSMDoubleVectorProperty::SafeDownCast(property))
  {
    u.held = u.index < d->GetNumberOfElements();
    u.before = u.held ? d->GetElement(u.index) : 0.0;
  }
  else if (auto* i = vtkSMIntVectorProperty::SafeDownCast(property))
  {
    u.held = u.index < i->GetNumberOfElements();
    u.beforeInteger = u.held ? i->GetElement(u.index) : 0;
  }
  else if (auto* id = vtkSMIdTypeVectorProperty::SafeDownCast(property))
  {
    u.held = u.index < id->GetNumberOfElements();
    u.beforeInteger = u.held ? id->GetElement(u.index) : 0;
  }
}

bool readsAsNumber(vtkSMProperty* property, const char* text)
{
  if (vtkSMDoubleVectorProperty::SafeDownCast(property))
  {
    return streamReads<double>(text);
  }
  if (vtkSMIntVectorProperty::SafeDownCast(property))
  {
    return streamReads<int>(text);
  }
  if (vtkSMIdTypeVectorProperty::SafeDownCast(property))
  {
    return streamReads<vtkIdType>(text);
  }
  return true; // strings, proxies: nothing to read as a number
}

/// An integer property's element set back to its value before loading.
void restoreInteger(vtkSMProperty* property, const Unread& u)
{
  if (auto* i = vtkSMIntVectorProperty::SafeDownCast(property))
  {
    i->SetElement(u.index, static_cast<int>(u.beforeInteger));
  }
  else if (auto* id = vtkSMIdTypeVectorProperty::SafeDownCast(property))
  {
    id->SetElement(u.index, static_cast<vtkIdType>(u.beforeInteger));
  }
}

/// Reads `u` again into its property; what was done, for the warning.
std::string readAgain(vtkSMProperty* property, const Unread& u)
{
  std::ostringstream said;
  if (auto* d = vtkSMDoubleVectorProperty::SafeDownCast(property))
  {
    double value = 0.0;
    if (wholeNumber(u.text, value))
    {
      d->SetElement(u.index, value);
      said << "the tracer gets " << value << ", as it would from a script";
    }
    else if (u.held)
    {
      d->SetElement(u.index, u.before);
      said << "it is not a number: " << u.property << " keeps " << u.before;
    }
    else
    {
      said << "it is not a number: " << u.property << " is 0";
    }
    return said.str();
  }
  auto* enumeration = property->FindDomain<vtkSMEnumerationDomain>();
  for (unsigned int k = 0; enumeration && k < enumeration->GetNumberOfEntries(); ++k)
  {
    const char* entry = enumeration->GetEntryText(k);
    if (entry && u.text == entry)
    {
      const int value = enumeration->GetEntryValue(k);
      Unread entryValue = u;
      entryValue.beforeInteger = value;
      restoreInteger(property, entryValue);
      said << "it is read as that entry, " << entry << " (" << value << ")";
      return said.str();
    }
  }
  if (u.held)
  {
    restoreInteger(property, u);
    said << "it is not " << (enumeration ? "one of its entries or " : "")
         << "an integer: " << u.property << " keeps " << u.beforeInteger;
  }
  else
  {
    said << "it is not " << (enumeration ? "one of its entries or " : "")
         << "an integer: " << u.property << " is 0";
  }
  return said.str();
}
} // namespace

int vtkSMBoundParticleTracerProxy::LoadXMLState(
  vtkPVXMLElement* element, vtkSMProxyLocator* locator)
{
  // The values ParaView's loading will read as 0, with the values before it.
  std::vector<Unread> unread;
  for (unsigned int p = 0; element && p < element->GetNumberOfNestedElements(); ++p)
  {
    vtkPVXMLElement* propertyElement = element->GetNestedElement(p);
    const char* name = propertyElement->GetAttribute("name");
    if (!propertyElement->GetName() || std::strcmp(propertyElement->GetName(), "Property") != 0 ||
      !name)
    {
      continue;
    }
    vtkSMProperty* property = this->GetProperty(name);
    if (property && property->GetInformationOnly())
    {
      continue; // the tracer's own report (ResolvedTimeStep...), not a setting
    }
    for (unsigned int e = 0; property && e < propertyElement->GetNumberOfNestedElements(); ++e)
    {
      vtkPVXMLElement* value = propertyElement->GetNestedElement(e);
      const char* text = value->GetAttribute("value");
      int index = -1;
      if (!value->GetName() || std::strcmp(value->GetName(), "Element") != 0 || !text ||
        !value->GetScalarAttribute("index", &index) || index < 0 || readsAsNumber(property, text))
      {
        continue;
      }
      Unread u;
      u.property = name;
      u.index = static_cast<unsigned int>(index);
      u.text = text;
      holdBefore(property, u);
      unread.push_back(u);
    }
  }
  const int loaded = this->Superclass::LoadXMLState(element, locator);
  for (const Unread& u : unread)
  {
    vtkSMProperty* property = this->GetProperty(u.property.c_str());
    const std::string done = readAgain(property, u);
    const std::string element =
      u.index > 0 ? " (element " + std::to_string(u.index) + ")" : std::string();
    vtkWarningMacro(<< "The state file gives " << u.property << element << " the value '" << u.text
                    << "', which ParaView's state loading reads as 0; " << done << ".");
  }
  return loaded;
}

void vtkSMBoundParticleTracerProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
