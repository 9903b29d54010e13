# Helpers that give every Capsula library and app the same shape:
#   packages/<name>/include/capsula/<name>/*.hpp   public headers
#   packages/<name>/src/*.cpp                        sources
# Warnings are PRIVATE so they never leak to users of our targets.

function(capsula_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
endfunction()

# Precompiled headers: the third-party headers that dominate compile time (parsing them is
# about half of a typical translation unit's time), in sets a target names by what it sees:
#   TEUCHOS  RCP, parameter lists, communicators, timers (every package: capsula::core)
#   EIGEN    Vec3 and small dense matrices (capsula::mesh and what depends on it)
#   TPETRA   distributed vectors and operators, with Kokkos under them
# A library that names `PRECOMPILE SHARED` reuses the one built for every library with its
# compile options (all the sets, built once per distinct COMPILE_OPTIONS: a precompiled
# header is only valid under the flags and macros it was made with); one with other macros
# (capsula::mesh, CGAL's) or flags that change the arithmetic (capsula::contour) names its
# own sets and compiles its own. The test executables share the one of capsula_test_support
# (tests/support).
option(CAPSULA_PRECOMPILED_HEADERS "Precompile the Trilinos, Eigen and GoogleTest headers" ON)
# Unity builds: a library's sources are compiled in batches of up to 8 per translation
# unit, so the templates they share (Teuchos, Eigen, Tpetra) are instantiated once per
# batch. Names private to a source file must then be unique within its package.
option(CAPSULA_UNITY_BUILD "Compile each library's sources in unity batches" ON)
# The linker: GNU gold where the compiler takes -fuse-ld=gold (Debian 12's binutils ships it).
# It links our executables against their 66 shared libraries (Trilinos, MPI, HDF5, ...) in about
# half the time of the default ld.bfd (test_run: 1.0 s against 2.0 s), 37 links in a clean build.
option(CAPSULA_GOLD_LINKER "Link with GNU gold when the compiler accepts -fuse-ld=gold" ON)
if(CAPSULA_GOLD_LINKER)
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=gold" CAPSULA_HAVE_GOLD_LINKER)
  if(CAPSULA_HAVE_GOLD_LINKER)
    add_link_options(-fuse-ld=gold)
  endif()
endif()
set(CAPSULA_PCH_STD <algorithm> <array> <cmath> <functional> <map> <memory> <sstream> <string> <vector>)
set(CAPSULA_PCH_TEUCHOS <Teuchos_RCP.hpp> <Teuchos_ParameterList.hpp> <Teuchos_Comm.hpp> <Teuchos_TimeMonitor.hpp>)
set(CAPSULA_PCH_EIGEN <Eigen/Core> <Eigen/Geometry>)
set(CAPSULA_PCH_TPETRA <Tpetra_Map.hpp> <Tpetra_MultiVector.hpp> <Tpetra_Operator.hpp>)

# capsula_precompile_headers(<target> <set>...): the standard headers and the named sets.
function(capsula_precompile_headers target)
  if(NOT CAPSULA_PRECOMPILED_HEADERS)
    return()
  endif()
  set(headers ${CAPSULA_PCH_STD})
  foreach(set_name IN LISTS ARGN)
    if(NOT DEFINED CAPSULA_PCH_${set_name})
      message(FATAL_ERROR "capsula_precompile_headers(${target}): no header set ${set_name}")
    endif()
    list(APPEND headers ${CAPSULA_PCH_${set_name}})
  endforeach()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# capsula_shared_precompiled_headers(<out-var> [<compile option>...]): the target whose
# precompiled headers (all the sets) a library with these compile options reuses, made on
# first use; its one source compiles nothing.
function(capsula_shared_precompiled_headers out_var)
  string(MAKE_C_IDENTIFIER "capsula_shared_pch${ARGN}" target)
  if(NOT TARGET ${target})
    add_library(${target} OBJECT ${PROJECT_SOURCE_DIR}/cmake/SharedPrecompiledHeaders.cpp)
    target_link_libraries(${target} PRIVATE capsula::deps::trilinos Eigen3::Eigen)
    target_compile_features(${target} PRIVATE cxx_std_17)
    target_compile_options(${target} PRIVATE ${ARGN})
    capsula_set_warnings(${target})
    capsula_precompile_headers(${target} TEUCHOS EIGEN TPETRA)
  endif()
  set(${out_var} ${target} PARENT_SCOPE)
endfunction()

# capsula_add_library(<name> SOURCES ... [DEPENDS ...] [COMPILE_OPTIONS <option>...]
#                     [PRECOMPILE SHARED | PRECOMPILE <set>...])
# Creates capsula_<name> with alias capsula::<name>; COMPILE_OPTIONS are private to it.
function(capsula_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRECOMPILE;COMPILE_OPTIONS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "capsula_add_library(${name}): list the sources explicitly")
  endif()
  add_library(capsula_${name} ${ARG_SOURCES})
  add_library(capsula::${name} ALIAS capsula_${name})
  target_include_directories(capsula_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_link_libraries(capsula_${name} PUBLIC ${ARG_DEPENDS})
  target_compile_features(capsula_${name} PUBLIC cxx_std_17)
  capsula_set_warnings(capsula_${name})
  target_compile_options(capsula_${name} PRIVATE ${ARG_COMPILE_OPTIONS})
  if(ARG_PRECOMPILE STREQUAL "SHARED")
    if(CAPSULA_PRECOMPILED_HEADERS)
      capsula_shared_precompiled_headers(shared ${ARG_COMPILE_OPTIONS})
      target_precompile_headers(capsula_${name} REUSE_FROM ${shared})
    endif()
  elseif(ARG_PRECOMPILE)
    capsula_precompile_headers(capsula_${name} ${ARG_PRECOMPILE})
  endif()
  if(CAPSULA_UNITY_BUILD)
    set_target_properties(capsula_${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
  if(CAPSULA_ENABLE_OPENMP)
    target_link_libraries(capsula_${name} PUBLIC OpenMP::OpenMP_CXX)
  endif()
endfunction()

# capsula_add_app(<name> SOURCES ... DEPENDS ... [COMPILE_OPTIONS <option>...])
# An app's sources reuse the shared precompiled headers made for its compile options (a
# thin main() otherwise spends its seconds parsing Teuchos and Tpetra).
function(capsula_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;COMPILE_OPTIONS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
  capsula_set_warnings(${name})
  target_compile_options(${name} PRIVATE ${ARG_COMPILE_OPTIONS})
  if(CAPSULA_PRECOMPILED_HEADERS)
    capsula_shared_precompiled_headers(shared ${ARG_COMPILE_OPTIONS})
    target_precompile_headers(${name} REUSE_FROM ${shared})
  endif()
endfunction()
