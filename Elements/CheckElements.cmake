# Writes the built-in elements afresh and fails if a committed .vtp differs.
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
execute_process(COMMAND "${TOOL}" "${SCRATCH}" RESULT_VARIABLE result)
if (result)
  message(FATAL_ERROR "the element writer failed: ${result}")
endif ()
file(GLOB written RELATIVE "${SCRATCH}" "${SCRATCH}/*.vtp")
foreach (name IN LISTS written)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files
    "${SCRATCH}/${name}" "${COMMITTED}/${name}" RESULT_VARIABLE differ)
  if (differ)
    message(FATAL_ERROR "Elements/${name} is out of date: run "
      "BoundParticlesWriteElements on the Elements folder and commit the result")
  endif ()
endforeach ()
list(LENGTH written count)
message(STATUS "all ${count} built-in elements are current")
