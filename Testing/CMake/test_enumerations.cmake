# The generator of the tracer's enumerated properties
# (cmake/BoundParticlesEnumerations.cmake), run as a developer would use it:
# a new enumerated property written only in the proxy XML gets its enum,
# setter, getter, member with the XML's default, clamp, cast into
# TracerConfig, checks against Core and GLSL #defines; an XML the generated
# C++ could not follow stops the configure with a message naming the
# property. Run with cmake -DSOURCE_DIR=... -DWORK_DIR=... -P.
cmake_minimum_required(VERSION 3.16...3.31)

set(_xml "${SOURCE_DIR}/Plugin/BoundParticles.xml")
file(READ "${_xml}" _original)
set(_anchor "      <IntVectorProperty name=\"Inertia\" label=\"Inertia\"")
string(FIND "${_original}" "${_anchor}" _at)
if (_at EQUAL -1)
  message(FATAL_ERROR "no Inertia property to add the scratch property before")
endif ()

# Writes the XML with `property` added to the tracer and runs the generator;
# `result` is its exit code, `output` what it said.
function (generate name property result output)
  string(SUBSTRING "${_original}" 0 ${_at} _head)
  string(SUBSTRING "${_original}" ${_at} -1 _tail)
  set(_dir "${WORK_DIR}/${name}")
  file(REMOVE_RECURSE "${_dir}")
  file(WRITE "${_dir}/BoundParticles.xml" "${_head}${property}${_tail}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -DBOUNDPARTICLES_ENUM_SOURCE_DIR=${SOURCE_DIR}
    -DBOUNDPARTICLES_ENUM_BINARY_DIR=${_dir} -DBOUNDPARTICLES_ENUM_XML=${_dir}/BoundParticles.xml
    -P "${SOURCE_DIR}/cmake/BoundParticlesEnumerations.cmake"
    RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  set(${result} "${_result}" PARENT_SCOPE)
  set(${output} "${_out}" PARENT_SCOPE)
endfunction ()

function (expect file text)
  file(READ "${file}" _content)
  string(FIND "${_content}" "${text}" _found)
  if (_found EQUAL -1)
    message(FATAL_ERROR "${file} lacks: ${text}")
  endif ()
endfunction ()

# A new property, with entries out of order as Engine's are.
generate(scratch [[
      <IntVectorProperty name="ScratchMode" label="Scratch Mode" command="SetScratchMode"
                         number_of_elements="1" default_values="1">
        <EnumerationDomain name="enum" vtk_enum="ScratchModes" core_enum="bp::ScratchKind"
                           core_field="trace.engine.scratchKind" shaders="1">
          <Entry value="2" text="Third" vtk="SCRATCH_THIRD" core="Third"/>
          <Entry value="0" text="First" vtk="SCRATCH_FIRST" core="First"/>
          <Entry value="1" text="Second One" vtk="SCRATCH_SECOND" core="SecondOne"/>
        </EnumerationDomain>
        <Documentation>A scratch property; its list [0, 2].</Documentation>
      </IntVectorProperty>
]] result output)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "the generator failed on a valid property: ${output}")
endif ()
set(_h "${WORK_DIR}/scratch/Filters/vtkBoundParticleTracer.h")
set(_cxx "${WORK_DIR}/scratch/Filters/vtkBoundParticleTracerEnumerations.cxx")
set(_glsl "${WORK_DIR}/scratch/Gpu/BoundParticlesShaderEnums.h")
expect("${_h}" "  enum ScratchModes\n  {\n    SCRATCH_FIRST = 0,\n    SCRATCH_SECOND = 1,\n    SCRATCH_THIRD = 2,\n  };\n  virtual void SetScratchMode(int value);\n  vtkGetMacro(ScratchMode, int);\n")
expect("${_h}" "A scratch property; its list [0,") # ";" and "[" kept
expect("${_h}" "  int ScratchMode = 1;\n")
expect("${_h}" "  virtual void SetInertia(int value);\n") # the others are still there
expect("${_cxx}" "BP_CLAMPED_SETTER(ScratchMode, int, SCRATCH_FIRST, SCRATCH_THIRD)\n")
expect("${_cxx}" "  c.trace.engine.scratchKind = bp::ScratchKind(this->ScratchMode);\n")
expect("${_cxx}" "static_assert(T::SCRATCH_SECOND == static_cast<int>(bp::ScratchKind::SecondOne),")
expect("${_cxx}" "    case SCRATCH_SECOND:\n      return \"Second One\";\n")
expect("${_glsl}" "{ \"BP_SCRATCH_KIND_SECOND_ONE\", static_cast<int>(bp::ScratchKind::SecondOne) },")

# What the generated C++ could not follow is refused, naming the property.
set(_bad_values [[
      <IntVectorProperty name="Gappy" label="Gappy" command="SetGappy"
                         number_of_elements="1" default_values="0">
        <EnumerationDomain name="enum" vtk_enum="GappyModes">
          <Entry value="0" text="A" vtk="GAPPY_A"/>
          <Entry value="2" text="C" vtk="GAPPY_C"/>
        </EnumerationDomain>
      </IntVectorProperty>
]])
set(_no_enum [[
      <IntVectorProperty name="Nameless" label="Nameless" command="SetNameless"
                         number_of_elements="1" default_values="0">
        <EnumerationDomain name="enum">
          <Entry value="0" text="A" vtk="NAMELESS_A"/>
        </EnumerationDomain>
      </IntVectorProperty>
]])
set(_no_core_name [[
      <IntVectorProperty name="Half" label="Half" command="SetHalf"
                         number_of_elements="1" default_values="0">
        <EnumerationDomain name="enum" vtk_enum="Halves" core_enum="bp::Half" core_field="half">
          <Entry value="0" text="A" vtk="HALF_A" core="A"/>
          <Entry value="1" text="B" vtk="HALF_B"/>
        </EnumerationDomain>
      </IntVectorProperty>
]])
set(_in_a_string [[
      <StringVectorProperty name="Texty" command="SetTexty" number_of_elements="1">
        <EnumerationDomain name="enum" vtk_enum="Texts">
          <Entry value="0" text="A" vtk="TEXT_A"/>
        </EnumerationDomain>
      </StringVectorProperty>
]])
foreach (_case IN ITEMS "bad_values;Gappy's values must be 0 to 1"
    "no_enum;Nameless's EnumerationDomain has no vtk_enum"
    "no_core_name;Half's entry 1 has no core name"
    "in_a_string;outside an IntVectorProperty")
  list(GET _case 0 _name)
  list(GET _case 1 _said)
  generate(${_name} "${_${_name}}" result output)
  if (result EQUAL 0)
    message(FATAL_ERROR "the generator took ${_name}")
  endif ()
  string(REGEX REPLACE "[ \n]+" " " output "${output}") # CMake wraps its messages
  string(FIND "${output}" "${_said}" _found)
  if (_found EQUAL -1)
    message(FATAL_ERROR "${_name}: the generator did not say \"${_said}\": ${output}")
  endif ()
endforeach ()
message(STATUS "the generator follows a new property and refuses what it cannot follow")
