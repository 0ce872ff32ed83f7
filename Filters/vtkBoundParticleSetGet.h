// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkBoundParticleSetGet.h
 * @brief The plugin's set/get macros, beside VTK's (vtkSetGet.h): a property
 * that takes one of Core's enumerations, and a number kept in a range.
 *
 * vtkBPEnumMacro(Integrator, bp::Integrator) declares, for the member
 * `bp::Integrator Integrator` (declared by the class, with its default):
 * - `virtual void SetIntegrator(int)`: what ParaView's IntVectorProperty and
 *   Python call (the wrapping sees it). A number that names no value of the
 *   enumeration (a script's, or an old state file's) is said with a warning
 *   and clamped to 0 .. bp::enumCount<bp::Integrator>() - 1;
 * - `virtual const char* GetIntegratorAsString() const`: the panel's text of
 *   the value (bp::enumName), as vtkProperty::GetInterpolationAsString;
 * - C++ only, `void SetIntegrator(bp::Integrator)` and
 *   `bp::Integrator GetIntegrator() const`, typed. The wrappers know no
 *   bp:: type, so they see neither.
 *
 * The pattern is the Topology ToolKit's ttkSetEnumMacro, with the clamp, its
 * warning and the text getter added. The enumerations and their texts live in
 * Core/Choices/BoundParticlesChoices.h; the proxy XML lists the same entries
 * by hand, and TestPropertyDefaults checks that every entry's value set
 * through SetX(int) reads back its text from GetXAsString().
 *
 * vtkBPClampedSetMacro(name, type, low, high) is vtkSetClampMacro, but a value
 * out of range is said with a warning rather than silently changed, and NaN
 * takes `low`.
 */
#ifndef vtkBoundParticleSetGet_h
#define vtkBoundParticleSetGet_h

#include "BoundParticlesChoices.h" // for bp::enumCount, bp::enumName
#include "vtkSetGet.h"

#ifdef __VTK_WRAP__
// What the wrappers see: the int setter and the text getter. ParaView 5.11's
// vtkWrapClientServer writes the same code from the full macro (it skips the
// typed pair, whose bp:: types it does not know); this branch spares other
// wrapper versions from having to decide that.
#define vtkBPEnumMacro(name, enumType)                                                             \
  virtual void Set##name(int value);                                                               \
  virtual const char* Get##name##AsString() const;
#else
#define vtkBPEnumMacro(name, enumType)                                                             \
  virtual void Set##name(int value)                                                                \
  {                                                                                                \
    const int last = bp::enumCount<enumType>() - 1;                                                \
    const int kept = value < 0 ? 0 : (value > last ? last : value);                                \
    if (kept != value)                                                                             \
    {                                                                                              \
      vtkWarningMacro(<< #name " " << value << " is none of 0 to " << last << "; using "           \
                      << bp::enumName(static_cast<enumType>(kept)) << ".");                        \
    }                                                                                              \
    if (this->name != static_cast<enumType>(kept))                                                 \
    {                                                                                              \
      this->name = static_cast<enumType>(kept);                                                    \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  virtual const char* Get##name##AsString() const                                                  \
  {                                                                                                \
    return bp::enumName(this->name);                                                               \
  }                                                                                                \
  void Set##name(enumType value)                                                                   \
  {                                                                                                \
    this->Set##name(static_cast<int>(value));                                                      \
  }                                                                                                \
  enumType Get##name() const                                                                       \
  {                                                                                                \
    return this->name;                                                                             \
  }
#endif

#define vtkBPClampedSetMacro(name, type, low, high)                                                \
  virtual void Set##name(type value)                                                               \
  {                                                                                                \
    const type lowest = static_cast<type>(low), highest = static_cast<type>(high);                 \
    const type clamped = !(value >= lowest) ? lowest : (value > highest ? highest : value);        \
    if (!(clamped == value))                                                                       \
    {                                                                                              \
      vtkWarningMacro(<< #name " " << value << " is outside [" << lowest << ", " << highest        \
                      << "]; using " << clamped << ".");                                           \
    }                                                                                              \
    if (this->name != clamped)                                                                     \
    {                                                                                              \
      this->name = clamped;                                                                        \
      this->Modified();                                                                            \
    }                                                                                              \
  }

#endif
