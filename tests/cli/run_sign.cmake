# Runs `cavity sign` once and checks its exit status, stdout and stderr. Variables:
#   CAVITY       the cavity executable
#   QUERIES      the query file
#   VIA_STDIN    ON: feed QUERIES on standard input; otherwise pass it as the file argument
#   OPTION       optional extra option (--stage or --oracle)
#   EXPECTED     file that stdout must equal; with --stage, each line must be "SIGN STAGE" and
#                the signs must equal EXPECTED
#   ERROR_REGEX  if set, the run must fail (non-zero exit) with stderr matching it
set(command "${CAVITY}" sign)
if(OPTION)
  list(APPEND command "${OPTION}")
endif()
if(VIA_STDIN)
  execute_process(COMMAND ${command} INPUT_FILE "${QUERIES}"
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
else()
  execute_process(COMMAND ${command} "${QUERIES}"
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
endif()

if(ERROR_REGEX)
  if(status EQUAL 0)
    message(FATAL_ERROR "expected a failure, got exit status 0; stdout:\n${out}")
  endif()
  if(NOT err MATCHES "${ERROR_REGEX}")
    message(FATAL_ERROR "stderr does not match '${ERROR_REGEX}':\n${err}")
  endif()
elseif(NOT status EQUAL 0)
  message(FATAL_ERROR "exit status ${status}; stderr:\n${err}")
endif()

if(OPTION STREQUAL "--stage")
  string(REGEX REPLACE "\n$" "" body "${out}")
  string(REPLACE "\n" ";" lines "${body}")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^(-1|0|1) (filter|adaptive|exact)$")
      message(FATAL_ERROR "not a 'SIGN STAGE' line: '${line}'")
    endif()
  endforeach()
  string(REGEX REPLACE " [a-z]+\n" "\n" out "${out}")
endif()
file(READ "${EXPECTED}" expected)
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "stdout differs from ${EXPECTED}:\n--- got\n${out}--- expected\n${expected}")
endif()
