# The tracer's enumerated properties, declared once: each is an
# IntVectorProperty of the BoundParticleTracer proxy in Plugin/BoundParticles.xml
# whose EnumerationDomain names its C++ side:
#
#   <EnumerationDomain name="enum" vtk_enum="InertiaModels" core_enum="bp::Inertia"
#                      core_field="trace.engine.inertia" shaders="1">
#     <Entry value="0" text="None" vtk="NO_INERTIA" core="None"/>
#
# (ParaView reads only the domain's name and each entry's text and value.)
# From that, configure time writes into the Filters module's build folder:
# - vtkBoundParticleTracer.h from Filters/vtkBoundParticleTracer.h.in: per
#   property the VTK enum (vtk_enum, the entries' vtk names and values), the
#   clamped setter's declaration, the getter and the member with the XML's
#   default (the ClientServer wrapping reads this header as ParaView calls it);
# - vtkBoundParticleTracerEnumerations.cxx: the setters (clamped to the
#   entries' values, which must run 0, 1, ... n-1), PrintEnumerations(),
#   ConfigureEnumerations() (TracerConfig's core_field = core_enum(value), for
#   a property with a core_enum) and a static_assert per entry that the VTK
#   value is the Core enumerator's (core_enum::core);
# and into Gpu's build folder BoundParticlesShaderEnums.h: for a property with
# shaders="1", each entry as a GLSL #define BP_<CORE_ENUM>_<CORE> (Gpu/ShaderSource.cpp),
# e.g. BP_INTEGRATOR_RK2. A new enumerated property is its XML entry, its Core
# enum and field (Core/Engine/EngineParameters.h) and its uses.

# Run as a script (cmake -P, Testing/CMake) it reads BOUNDPARTICLES_ENUM_XML
# and BOUNDPARTICLES_ENUM_SOURCE_DIR and writes under BOUNDPARTICLES_ENUM_BINARY_DIR.
if (CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.16...3.31)
  set(_bp_source "${BOUNDPARTICLES_ENUM_SOURCE_DIR}")
  set(_bp_binary "${BOUNDPARTICLES_ENUM_BINARY_DIR}")
  set(_bp_enum_xml "${BOUNDPARTICLES_ENUM_XML}")
else ()
  set(_bp_source "${CMAKE_CURRENT_SOURCE_DIR}")
  set(_bp_binary "${CMAKE_CURRENT_BINARY_DIR}")
  set(_bp_enum_xml "${_bp_source}/Plugin/BoundParticles.xml")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_bp_enum_xml}"
    "${_bp_source}/Filters/vtkBoundParticleTracer.h.in" "${CMAKE_CURRENT_LIST_FILE}")
endif ()

# The value of attribute `name` in the XML tag `tag` ("" when absent).
function (_bp_attribute tag name out)
  if (tag MATCHES " ${name}=\"([^\"]*)\"")
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  else ()
    set(${out} "" PARENT_SCOPE)
  endif ()
endfunction ()

# MaxeyRiley -> MAXEY_RILEY, RK2 -> RK2.
function (_bp_upper_snake name out)
  string(REGEX REPLACE "([a-z0-9])([A-Z])" "\\1_\\2" _snake "${name}")
  string(TOUPPER "${_snake}" _snake)
  set(${out} "${_snake}" PARENT_SCOPE)
endfunction ()

# `text` as `///` comment lines of at most 100 columns, indented two spaces.
function (_bp_comment text out)
  # List separators and brackets (which group list items) stand aside.
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<open>" text "${text}")
  string(REPLACE "]" "<close>" text "${text}")
  string(REPLACE " " ";" _words "${text}")
  set(_lines "")
  set(_line "  ///")
  foreach (_word IN LISTS _words)
    string(LENGTH "${_line} ${_word}" _length)
    if (_length GREATER 100 AND NOT _line STREQUAL "  ///")
      string(APPEND _lines "${_line}\n")
      set(_line "  ///")
    endif ()
    string(APPEND _line " ${_word}")
  endforeach ()
  string(APPEND _lines "${_line}\n")
  string(REPLACE "<semicolon>" ";" _lines "${_lines}")
  string(REPLACE "<open>" "[" _lines "${_lines}")
  string(REPLACE "<close>" "]" _lines "${_lines}")
  set(${out} "${_lines}" PARENT_SCOPE)
endfunction ()

# Writes `text` to `path` only when it changed, so that nothing rebuilds
# (or re-wraps) after a configure that changed nothing.
function (_bp_write_if_changed path text)
  file(WRITE "${path}.new" "${text}")
  configure_file("${path}.new" "${path}" COPYONLY)
endfunction ()

file(READ "${_bp_enum_xml}" _bp_xml)
string(FIND "${_bp_xml}" "<BoundParticleTracerProxy name=\"BoundParticleTracer\"" _bp_begin)
if (_bp_begin EQUAL -1)
  message(FATAL_ERROR "${_bp_enum_xml}: no BoundParticleTracer proxy")
endif ()
string(SUBSTRING "${_bp_xml}" ${_bp_begin} -1 _bp_rest)
string(FIND "${_bp_rest}" "</BoundParticleTracerProxy>" _bp_end)
string(SUBSTRING "${_bp_rest}" 0 ${_bp_end} _bp_rest)

set(_bp_declarations "")
set(_bp_members "")
set(_bp_setters "")
set(_bp_print "")
set(_bp_configure "")
set(_bp_asserts "")
set(_bp_shader_enums "")
while (TRUE)
  string(FIND "${_bp_rest}" "<EnumerationDomain" _bp_at)
  if (_bp_at EQUAL -1)
    break ()
  endif ()
  # The property: the last IntVectorProperty opened before the domain.
  string(SUBSTRING "${_bp_rest}" 0 ${_bp_at} _bp_before)
  string(FIND "${_bp_before}" "<IntVectorProperty" _bp_open REVERSE)
  set(_bp_inside "</IntVectorProperty>")
  if (NOT _bp_open EQUAL -1)
    string(SUBSTRING "${_bp_before}" ${_bp_open} -1 _bp_property)
    string(SUBSTRING "${_bp_property}" 1 -1 _bp_inside) # after its own opening "<"
  endif ()
  if (_bp_inside MATCHES "</IntVectorProperty>|<[A-Za-z]+VectorProperty")
    message(FATAL_ERROR "${_bp_enum_xml}: an EnumerationDomain of the tracer outside an "
      "IntVectorProperty (the enumerations generated from it are ints)")
  endif ()
  string(FIND "${_bp_property}" ">" _bp_close)
  string(SUBSTRING "${_bp_property}" 0 ${_bp_close} _bp_property)
  string(REGEX REPLACE "[ \n]+" " " _bp_property "${_bp_property}")
  _bp_attribute("${_bp_property}" name _bp_name)
  _bp_attribute("${_bp_property}" label _bp_label)
  _bp_attribute("${_bp_property}" command _bp_command)
  _bp_attribute("${_bp_property}" default_values _bp_default)
  if (NOT _bp_command STREQUAL "Set${_bp_name}")
    message(FATAL_ERROR "${_bp_enum_xml}: property ${_bp_name}'s command is not Set${_bp_name}")
  endif ()
  # The domain, its entries, and the property's documentation after it.
  string(SUBSTRING "${_bp_rest}" ${_bp_at} -1 _bp_rest)
  string(FIND "${_bp_rest}" "</EnumerationDomain>" _bp_domain_end)
  string(SUBSTRING "${_bp_rest}" 0 ${_bp_domain_end} _bp_domain)
  string(SUBSTRING "${_bp_rest}" ${_bp_domain_end} -1 _bp_rest)
  string(REGEX REPLACE "[ \n]+" " " _bp_domain "${_bp_domain}")
  string(FIND "${_bp_domain}" ">" _bp_close)
  string(SUBSTRING "${_bp_domain}" 0 ${_bp_close} _bp_domain_tag)
  _bp_attribute("${_bp_domain_tag}" vtk_enum _bp_vtk_enum)
  _bp_attribute("${_bp_domain_tag}" core_enum _bp_core_enum)
  _bp_attribute("${_bp_domain_tag}" core_field _bp_core_field)
  _bp_attribute("${_bp_domain_tag}" shaders _bp_shaders)
  if (NOT _bp_vtk_enum)
    message(FATAL_ERROR "${_bp_enum_xml}: ${_bp_name}'s EnumerationDomain has no vtk_enum")
  endif ()
  set(_bp_doc "")
  string(FIND "${_bp_rest}" "</IntVectorProperty>" _bp_property_end)
  string(SUBSTRING "${_bp_rest}" 0 ${_bp_property_end} _bp_tail)
  if (_bp_tail MATCHES "<Documentation>([^<]*)</Documentation>")
    string(REGEX REPLACE "[ \n]+" " " _bp_doc "${CMAKE_MATCH_1}")
  endif ()

  string(REGEX MATCHALL "<Entry [^>]*>" _bp_entries "${_bp_domain}")
  list(LENGTH _bp_entries _bp_count)
  math(EXPR _bp_last "${_bp_count} - 1")
  set(_bp_enumerators "")
  set(_bp_names_by_value "")
  set(_bp_texts "")
  foreach (_bp_value RANGE ${_bp_last})
    set(_bp_found FALSE)
    foreach (_bp_entry IN LISTS _bp_entries)
      _bp_attribute("${_bp_entry}" value _bp_entry_value)
      if (_bp_entry_value STREQUAL "${_bp_value}")
        set(_bp_found TRUE)
        _bp_attribute("${_bp_entry}" vtk _bp_vtk)
        _bp_attribute("${_bp_entry}" core _bp_core)
        _bp_attribute("${_bp_entry}" text _bp_text)
        if (NOT _bp_vtk)
          message(FATAL_ERROR "${_bp_enum_xml}: ${_bp_name}'s entry ${_bp_value} has no vtk name")
        endif ()
        string(APPEND _bp_enumerators "    ${_bp_vtk} = ${_bp_value},\n")
        list(APPEND _bp_names_by_value "${_bp_vtk}")
        string(APPEND _bp_texts "    case ${_bp_vtk}:\n      return \"${_bp_text}\";\n")
        if (_bp_core_enum)
          if (NOT _bp_core)
            message(FATAL_ERROR "${_bp_enum_xml}: ${_bp_name}'s entry ${_bp_value} has no core name")
          endif ()
          string(APPEND _bp_asserts "static_assert(T::${_bp_vtk} == static_cast<int>(${_bp_core_enum}::${_bp_core}),\n  \"${_bp_name}: ${_bp_vtk} is ${_bp_core_enum}::${_bp_core}\");\n")
          if (_bp_shaders)
            string(REGEX REPLACE "^bp::" "" _bp_type "${_bp_core_enum}")
            _bp_upper_snake("${_bp_type}" _bp_type_upper)
            _bp_upper_snake("${_bp_core}" _bp_core_upper)
            string(APPEND _bp_shader_enums "  { \"BP_${_bp_type_upper}_${_bp_core_upper}\", static_cast<int>(${_bp_core_enum}::${_bp_core}) },\n")
          endif ()
        endif ()
      endif ()
    endforeach ()
    if (NOT _bp_found)
      message(FATAL_ERROR "${_bp_enum_xml}: ${_bp_name}'s values must be 0 to ${_bp_last}; ${_bp_value} is missing")
    endif ()
  endforeach ()
  list(GET _bp_names_by_value 0 _bp_lowest)
  list(GET _bp_names_by_value ${_bp_last} _bp_highest)

  _bp_comment("${_bp_label}, as the panel documents it: ${_bp_doc} Set${_bp_name} clamps to [${_bp_lowest}, ${_bp_highest}] and warns of a value outside." _bp_lines)
  string(APPEND _bp_declarations
    "  ///@{\n"
    "${_bp_lines}"
    "  enum ${_bp_vtk_enum}\n  {\n${_bp_enumerators}  };\n"
    "  virtual void Set${_bp_name}(int value);\n"
    "  vtkGetMacro(${_bp_name}, int);\n"
    "  ///@}\n\n")
  string(APPEND _bp_members "  int ${_bp_name} = ${_bp_default};\n")
  string(APPEND _bp_setters "BP_CLAMPED_SETTER(${_bp_name}, int, ${_bp_lowest}, ${_bp_highest})\n")
  string(APPEND _bp_print
    "  os << indent << \"${_bp_name}: \" << [](int value)\n  {\n    switch (value)\n    {\n${_bp_texts}"
    "    default:\n      return \"?\";\n    }\n  }(this->${_bp_name}) << \"\\n\";\n")
  if (_bp_core_enum)
    if (NOT _bp_core_field)
      message(FATAL_ERROR "${_bp_enum_xml}: ${_bp_name} has a core_enum but no core_field")
    endif ()
    string(APPEND _bp_configure "  c.${_bp_core_field} = ${_bp_core_enum}(this->${_bp_name});\n")
  endif ()
endwhile ()

# The public class header, with the enumerations in their places.
file(READ "${_bp_source}/Filters/vtkBoundParticleTracer.h.in" _bp_header)
string(REPLACE "@BOUNDPARTICLES_ENUMERATED_PROPERTIES@" "${_bp_declarations}" _bp_header "${_bp_header}")
string(REPLACE "@BOUNDPARTICLES_ENUMERATED_MEMBERS@" "${_bp_members}" _bp_header "${_bp_header}")
_bp_write_if_changed("${_bp_binary}/Filters/vtkBoundParticleTracer.h" "${_bp_header}")

_bp_write_if_changed("${_bp_binary}/Filters/vtkBoundParticleTracerEnumerations.cxx"
"// Generated by cmake/BoundParticlesEnumerations.cmake from Plugin/BoundParticles.xml.
// The tracer's enumerated properties: their setters, what PrintSelf says of
// them, how they reach the VTK-free core (a plain cast, which the
// static_asserts make safe: each VTK value is its Core enumerator's).
#include \"TracerClampedSetter.h\"
#include \"TracerConfig.h\"
#include \"vtkBoundParticleTracer.h\"

namespace
{
using T = vtkBoundParticleTracer;
${_bp_asserts}}

${_bp_setters}
void vtkBoundParticleTracer::PrintEnumerations(ostream& os, vtkIndent indent) const
{
${_bp_print}}

void vtkBoundParticleTracer::ConfigureEnumerations(bpvtk::TracerConfig& c) const
{
${_bp_configure}}
")

_bp_write_if_changed("${_bp_binary}/Gpu/BoundParticlesShaderEnums.h"
"// Generated by cmake/BoundParticlesEnumerations.cmake from Plugin/BoundParticles.xml:
// the Core enumerators the shaders compare with, as GLSL #define names.
#ifndef BoundParticlesShaderEnums_h
#define BoundParticlesShaderEnums_h
#include \"EngineParameters.h\"

namespace bp
{
struct ShaderEnumerator
{
  const char* name;
  int value;
};
static const ShaderEnumerator ShaderEnumerators[] = {
${_bp_shader_enums}};
} // namespace bp

#endif
")
