# Runs a command and checks both its exit code and its output, which ctest's
# PASS_REGULAR_EXPRESSION cannot do together (a matching message with the wrong exit code
# would pass there).
#
#   cmake -DEXIT_CODE=<n> -DMATCHES=<regex> [-DNOT_MATCHES=<regex>] [-DWORKING_DIRECTORY=<dir>]
#         -P run_expecting.cmake -- <command> [args...]
#
# stdout and stderr are matched together, as a user reads them in a terminal. NOT_MATCHES
# must find nothing (a message printed twice, an MPI_Abort banner). Neither regex may hold
# ';' (CMake splits arguments there): write '.' for it.
set(_command)
set(_after_separator FALSE)
math(EXPR _last "${CMAKE_ARGC} - 1")
foreach(_i RANGE 0 ${_last})
  if(_after_separator)
    list(APPEND _command "${CMAKE_ARGV${_i}}")
  elseif("${CMAKE_ARGV${_i}}" STREQUAL "--")
    set(_after_separator TRUE)
  endif()
endforeach()
list(LENGTH _command _words)
if(_words EQUAL 0)
  message(FATAL_ERROR "run_expecting.cmake: no command after --")
endif()
if(NOT DEFINED EXIT_CODE OR NOT DEFINED MATCHES)
  message(FATAL_ERROR "run_expecting.cmake: EXIT_CODE and MATCHES are required")
endif()
if(NOT WORKING_DIRECTORY)
  set(WORKING_DIRECTORY ".")
endif()

execute_process(COMMAND ${_command}
  WORKING_DIRECTORY "${WORKING_DIRECTORY}"
  RESULT_VARIABLE _result OUTPUT_VARIABLE _output ERROR_VARIABLE _output)
message("${_output}")
if(NOT "${_result}" STREQUAL "${EXIT_CODE}")
  message(FATAL_ERROR "exit code ${_result}, expected ${EXIT_CODE}")
endif()
string(REGEX MATCH "${MATCHES}" _matched "${_output}")
if("${_matched}" STREQUAL "")
  message(FATAL_ERROR "the output does not match: ${MATCHES}")
endif()
if(NOT_MATCHES)
  string(REGEX MATCH "${NOT_MATCHES}" _unwanted "${_output}")
  if(NOT "${_unwanted}" STREQUAL "")
    message(FATAL_ERROR "the output contains what it must not: ${_unwanted}")
  endif()
endif()
