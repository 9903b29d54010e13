# Finds the whole stack once; packages link what they need through the
# capsula::deps::* interface targets defined here.

find_package(MPI REQUIRED COMPONENTS C CXX)
# Capsula calls MPI through its C interface (and Teuchos's). Open MPI's mpi.h would otherwise
# define the deprecated C++ bindings' classes, whose inline virtual functions every translation
# unit that includes it compiles again (about 14 kB of code per object file).
add_compile_definitions(OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX)

# Debian's Trilinos 13.2 has no imported targets: wrap its variables in an
# interface target so packages can link it like any other dependency.
find_package(Trilinos REQUIRED COMPONENTS Teuchos Tpetra Belos)
add_library(capsula_deps_trilinos INTERFACE)
target_include_directories(capsula_deps_trilinos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(capsula_deps_trilinos INTERFACE ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)
target_link_directories(capsula_deps_trilinos INTERFACE ${Trilinos_LIBRARY_DIRS})
add_library(capsula::deps::trilinos ALIAS capsula_deps_trilinos)

set(HDF5_PREFER_PARALLEL ON)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(WARNING "Capsula: the HDF5 found is not parallel (install libhdf5-openmpi-dev)")
endif()
add_library(capsula_deps_hdf5 INTERFACE)
target_include_directories(capsula_deps_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
target_link_libraries(capsula_deps_hdf5 INTERFACE ${HDF5_C_LIBRARIES} ${HDF5_LIBRARIES} MPI::MPI_C)
target_compile_definitions(capsula_deps_hdf5 INTERFACE ${HDF5_DEFINITIONS})
add_library(capsula::deps::hdf5 ALIAS capsula_deps_hdf5)

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CGAL REQUIRED)
include(CGAL_Eigen3_support)   # defines CGAL::Eigen3_support (Monge jet fitting needs it)
find_package(Boost REQUIRED)

# FFTW 3 (Debian libfftw3-dev) ships no CMake config: found through its pkg-config file.
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
add_library(capsula_deps_fftw INTERFACE)
target_link_libraries(capsula_deps_fftw INTERFACE PkgConfig::FFTW3)
add_library(capsula::deps::fftw ALIAS capsula_deps_fftw)

if(CAPSULA_ENABLE_OPENMP)
  find_package(OpenMP REQUIRED COMPONENTS CXX)
endif()

find_package(GTest)
find_package(benchmark QUIET)
