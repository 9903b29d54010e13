# Helpers that give every Capsula library and app the same shape:
#   packages/<name>/include/capsula/<name>/*.hpp   public headers
#   packages/<name>/src/*.cpp                        sources
# Warnings are PRIVATE so they never leak to users of our targets.

function(capsula_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
endfunction()

# capsula_add_library(<name> SOURCES ... [DEPENDS ...])
# Creates capsula_<name> with alias capsula::<name>.
function(capsula_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
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
  if(CAPSULA_ENABLE_OPENMP)
    target_link_libraries(capsula_${name} PUBLIC OpenMP::OpenMP_CXX)
  endif()
endfunction()

# capsula_add_app(<name> SOURCES ... DEPENDS ...)
function(capsula_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
  capsula_set_warnings(${name})
endfunction()
