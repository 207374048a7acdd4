# Fails when the predicate object code contains fused multiply-add instructions the compiler made
# by contracting a * b + c, which rounds once for two operations and so breaks the error-free
# transformations and the filters' error bounds (predicates.md §1.3). Run as: cmake -DOBJDUMP=... -DLIBRARY=... -P check_no_fma.cmake
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
set(fused_regex "[\t ](vfn?m(add|sub)[0-9a-z]*|fn?m(add|sub)|fml[as])[\t ][^\n]*")
# The one exception: functions named *fused* are the double-double stages' fused variants, which
# call __builtin_fma explicitly to find a product's exact rounding error (double_double.h,
# fused_products.h); the compiler still contracts nothing there (-ffp-contract=off). Every other
# function must have none. objdump separates functions by a blank line.
string(REPLACE ";" "," disassembly "${disassembly}")
string(REPLACE "\n\n" ";" functions "${disassembly}")
set(count 0)
set(allowed 0)
set(first "")
foreach(function IN LISTS functions)
  string(REGEX MATCHALL "${fused_regex}" fused "${function}")
  list(LENGTH fused n)
  if(n EQUAL 0)
    continue()
  endif()
  string(REGEX MATCH "<[^>\n]*>:" name "${function}")
  if(name MATCHES "fused")
    math(EXPR allowed "${allowed} + ${n}")
  else()
    math(EXPR count "${count} + ${n}")
    list(GET fused 0 example)
    string(APPEND first "\n${name}${example}")
  endif()
endforeach()
if(count GREATER 0)
  message(FATAL_ERROR "${count} fused multiply-add instructions in ${LIBRARY} outside its fused "
                      "variants, e.g.${first}")
endif()
message(STATUS "no fused multiply-add in ${LIBRARY} but for ${allowed} in its fused variants")
