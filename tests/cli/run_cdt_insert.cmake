# Runs `cavity cdt POLY -o PREFIX --protect --convex-hull --insert POINTS` and checks the output
# with `cavity check PREFIX.node PREFIX.ele --poly PREFIX.poly --convex-hull`: the PLC (a triangle
# and a segment in a box with no walls) bounds no domain, so the whole hull is the mesh. Variables:
#   CAVITY          the cavity executable
#   POLY, POINTS    the PLC and the points to insert
#   PREFIX          output prefix (its files are removed first)
#   ALL_OR_NOTHING  ON: pass --all-or-nothing; the run must then fail and write nothing
#   STDERR_REGEX    stderr of the cdt run must match it (the refused points)
file(REMOVE ${PREFIX}.node ${PREFIX}.ele ${PREFIX}.face ${PREFIX}.vtu ${PREFIX}.poly)
set(command "${CAVITY}" cdt "${POLY}" -o "${PREFIX}" --protect --convex-hull
    --insert "${POINTS}")
if(ALL_OR_NOTHING)
  list(APPEND command --all-or-nothing)
endif()
execute_process(COMMAND ${command} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT err MATCHES "${STDERR_REGEX}")
  message(FATAL_ERROR "stderr does not match '${STDERR_REGEX}':\n${err}")
endif()
if(ALL_OR_NOTHING)
  if(status EQUAL 0)
    message(FATAL_ERROR "--all-or-nothing accepted a refused point; stdout:\n${out}")
  endif()
  foreach(suffix node ele face vtu poly)
    if(EXISTS ${PREFIX}.${suffix})
      message(FATAL_ERROR "--all-or-nothing failed but wrote ${PREFIX}.${suffix}")
    endif()
  endforeach()
  return()
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "exit status ${status}; stderr:\n${err}")
endif()
if(NOT out MATCHES "inserted [1-9][0-9]* of 7 points")
  message(FATAL_ERROR "no insertion summary in stdout:\n${out}")
endif()
execute_process(COMMAND "${CAVITY}" check "${PREFIX}.node" "${PREFIX}.ele" --poly "${PREFIX}.poly"
                --convex-hull
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT out MATCHES "valid: constrained Delaunay")
  message(FATAL_ERROR "cavity check --poly ${PREFIX}.poly failed (${status}):\n${out}${err}")
endif()
# The same mesh against other points (the inserted points alone) is refused.
execute_process(COMMAND "${CAVITY}" check "${POINTS}" "${PREFIX}.ele" --poly "${PREFIX}.poly"
                --convex-hull
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(status EQUAL 0 OR NOT err MATCHES "points, but .*\\.poly has")
  message(FATAL_ERROR "check --poly accepted a point file unlike the PLC (${status}):\n${out}${err}")
endif()
