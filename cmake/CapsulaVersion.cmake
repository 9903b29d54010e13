# Records the git SHA at configure time (re-run at build time so it follows commits).
set(CAPSULA_VERSION_IN ${CMAKE_CURRENT_LIST_DIR}/Version.cpp.in)
set(CAPSULA_VERSION_OUT ${CMAKE_BINARY_DIR}/generated/capsula_version.cpp)
add_custom_target(capsula_git_version ALL
  BYPRODUCTS ${CAPSULA_VERSION_OUT}
  COMMAND ${CMAKE_COMMAND} -DSRC=${CMAKE_SOURCE_DIR} -DIN=${CAPSULA_VERSION_IN}
          -DOUT=${CAPSULA_VERSION_OUT} -DVERSION=${PROJECT_VERSION}
          -P ${CMAKE_CURRENT_LIST_DIR}/WriteVersion.cmake
  COMMENT "Recording the git SHA")
