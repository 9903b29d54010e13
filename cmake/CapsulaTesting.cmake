# Test registration helpers.
#
# capsula_add_unit_test(<name> SOURCES ... DEPENDS ... [LABELS ...] [OPTIMIZED])
#   A GoogleTest executable (one per package); every TEST() becomes its own ctest entry
#   (label "unit").
# capsula_add_mpi_test(<name> SOURCES ... DEPENDS ... [RANKS n] [LABELS ...])
#   A GoogleTest executable run as one ctest entry under mpiexec -n <RANKS> (default 2),
#   label "mpi" (CMake 3.25 cannot discover gtest cases through mpiexec).
# Both link tests/support (a main() that owns MPI/Tpetra and silences non-root output).

include(GoogleTest)
if(NOT GTest_FOUND)
  message(FATAL_ERROR "GoogleTest is required for the tests (install libgtest-dev)")
endif()

# Open MPI refuses to run as root and to oversubscribe 2 cores without these.
set(CAPSULA_MPIEXEC_FLAGS ${MPIEXEC_NUMPROC_FLAG})
set(CAPSULA_MPIEXEC_PREFLAGS --oversubscribe)
execute_process(COMMAND id -u OUTPUT_VARIABLE _capsula_uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(_capsula_uid STREQUAL "0")
  list(APPEND CAPSULA_MPIEXEC_PREFLAGS --allow-run-as-root)
endif()

# The tests' own code compiles at -O1 in Release builds, the libraries they test at the build
# type's -O3: on a test batch -O1 takes about half the compiler time of -O3 (7.9 s against
# 14.9 s for test_run's first batch), and the results agree to round-off (docs/developer-guide.md,
# "Build time"). An inline function that both a test and a library compile out of line runs the
# test's copy, which the linker meets first.
set(CAPSULA_TEST_OPTIMIZATION "-O1" CACHE STRING
  "Optimization flag of the test executables' own code in Release builds")
if(NOT CAPSULA_TEST_OPTIMIZATION MATCHES "^-O([0-3sgz]|fast)?$")
  message(FATAL_ERROR "CAPSULA_TEST_OPTIMIZATION = '${CAPSULA_TEST_OPTIMIZATION}' is not a GCC "
    "optimization flag (-O0, -O1, -O2, -O3, -Os, -Og, ...)")
endif()

# capsula_set_test_options(<target>): the tests' optimization flag.
function(capsula_set_test_options name)
  target_compile_options(${name} PRIVATE $<$<CONFIG:Release>:${CAPSULA_TEST_OPTIMIZATION}>)
endfunction()

# Every test executable reuses capsula_test_support's precompiled headers, so it needs the same
# flags: GCC takes the optimization level from the precompiled header, not the command line.
function(capsula_reuse_test_headers name)
  capsula_set_test_options(${name})
  if(CAPSULA_PRECOMPILED_HEADERS)
    target_precompile_headers(${name} REUSE_FROM capsula_test_support)
  endif()
endfunction()

# One executable per package: its sources are compiled in unity batches (CAPSULA_UNITY_BUILD),
# except those marked SKIP_UNITY_BUILD_INCLUSION because file-local names clash.
# OPTIMIZED keeps the build type's optimization for a test whose own code holds the loops it
# times or runs at length (a library template it instantiates); it compiles without the
# precompiled headers, which carry -O1.
function(capsula_add_unit_test name)
  cmake_parse_arguments(ARG "OPTIMIZED" "TIMEOUT" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE capsula_test_support ${ARG_DEPENDS})
  capsula_set_warnings(${name})
  if(ARG_OPTIMIZED)
    set_target_properties(${name} PROPERTIES DISABLE_PRECOMPILE_HEADERS ON)
  else()
    capsula_reuse_test_headers(${name})
  endif()
  if(CAPSULA_UNITY_BUILD)
    set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  gtest_discover_tests(${name}
    PROPERTIES LABELS "unit;${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT}
    DISCOVERY_TIMEOUT 60)
endfunction()

function(capsula_add_mpi_test name)
  cmake_parse_arguments(ARG "" "RANKS;TIMEOUT" "SOURCES;DEPENDS;LABELS;ARGS" ${ARGN})
  if(NOT ARG_RANKS)
    set(ARG_RANKS 2)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  if(ARG_SOURCES)
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE capsula_test_support ${ARG_DEPENDS})
    capsula_set_warnings(${name})
    capsula_reuse_test_headers(${name})
    set(_exe $<TARGET_FILE:${name}>)
  else()
    message(FATAL_ERROR "capsula_add_mpi_test(${name}): SOURCES required")
  endif()
  add_test(NAME ${name}
    COMMAND ${MPIEXEC_EXECUTABLE} ${CAPSULA_MPIEXEC_FLAGS} ${ARG_RANKS}
            ${CAPSULA_MPIEXEC_PREFLAGS} ${_exe} ${ARG_ARGS})
  set_tests_properties(${name} PROPERTIES
    LABELS "mpi;${ARG_LABELS}" PROCESSORS ${ARG_RANKS} TIMEOUT ${ARG_TIMEOUT})
endfunction()

# capsula_add_mpi_command_test(<name> COMMAND <exe> args... [RANKS n] [LABELS ...])
#   Runs an existing executable (an app, say) under mpiexec, label "mpi".
function(capsula_add_mpi_command_test name)
  cmake_parse_arguments(ARG "" "RANKS;TIMEOUT;WORKING_DIRECTORY" "COMMAND;LABELS" ${ARGN})
  if(NOT ARG_RANKS)
    set(ARG_RANKS 2)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  if(NOT ARG_WORKING_DIRECTORY)
    set(ARG_WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  add_test(NAME ${name}
    COMMAND ${MPIEXEC_EXECUTABLE} ${CAPSULA_MPIEXEC_FLAGS} ${ARG_RANKS}
            ${CAPSULA_MPIEXEC_PREFLAGS} ${ARG_COMMAND}
    WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY})
  set_tests_properties(${name} PROPERTIES
    LABELS "mpi;${ARG_LABELS}" PROCESSORS ${ARG_RANKS} TIMEOUT ${ARG_TIMEOUT})
endfunction()
