# Fails when the predicate object code contains fused multiply-add instructions, which round once
# for two operations and so break the error-free transformations and the filters' error bounds
# (predicates.md §1.3). Run as: cmake -DOBJDUMP=... -DLIBRARY=... -P check_no_fma.cmake
if(NOT OBJDUMP OR NOT EXISTS "${OBJDUMP}")
  find_program(objdump_on_path objdump)
  set(OBJDUMP "${objdump_on_path}")
endif()
if(NOT OBJDUMP)
  message("SKIPPED: objdump not found, cannot inspect ${LIBRARY}")
  return()
endif()
execute_process(COMMAND "${OBJDUMP}" -d --no-show-raw-insn "${LIBRARY}"
                OUTPUT_VARIABLE disassembly RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} -d ${LIBRARY} failed with status ${status}")
endif()
# Guard against a vacuous pass: the disassembly must contain the predicates and some arithmetic.
if(NOT disassembly MATCHES "orient3d" OR NOT disassembly MATCHES "mulsd|mulpd|fmul")
  message(FATAL_ERROR "no predicate code found in the disassembly of ${LIBRARY}")
endif()
# x86 (vfmadd132sd, vfnmsub231pd, ...) and AArch64 (fmadd, fmsub, fnmadd, fnmsub, fmla, fmls).
string(REGEX MATCHALL "[\t ](vfn?m(add|sub)[0-9a-z]*|fn?m(add|sub)|fml[as])[\t ][^\n]*"
       fused "${disassembly}")
list(LENGTH fused count)
if(count GREATER 0)
  list(SUBLIST fused 0 5 first)
  string(REPLACE ";" "\n" first "${first}")
  message(FATAL_ERROR "${count} fused multiply-add instructions in ${LIBRARY}, e.g.\n${first}")
endif()
message(STATUS "no fused multiply-add in ${LIBRARY}")
