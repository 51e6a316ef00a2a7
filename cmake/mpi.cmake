# SPDX-License-Identifier: Apache-2.0
# `toroid render` under mpirun (src/cmd/mpi/): TOROID_MPI AUTO builds it when
# MPI is found, ON requires it, OFF leaves it out. Without it, toroid started
# by mpirun says so and exits 2. Sets TOROID_HAVE_MPI for the tests.
include(${PROJECT_SOURCE_DIR}/cmake/optional_feature.cmake)
set(TOROID_HAVE_MPI OFF)
toroid_feature_mode(TOROID_MPI toroid_mpi_mode)
if(toroid_mpi_mode STREQUAL "OFF")
  return()
endif()
# An instrumented toroid would report the MPI library's own allocations and
# threads, which are not instrumented.
toroid_sanitized_build(toroid_sanitized)
if(toroid_sanitized)
  toroid_feature_unavailable(${toroid_mpi_mode}
    "TOROID_MPI=ON cannot be combined with a sanitized build (the MPI library is not instrumented)"
    "toroid: MPI rendering is skipped in a sanitized build")
  return()
endif()
find_package(MPI COMPONENTS CXX QUIET)
if(NOT MPI_CXX_FOUND)
  toroid_feature_unavailable(${toroid_mpi_mode}
    "TOROID_MPI=ON, but MPI was not found: install Open MPI (Debian: apt-get install libopenmpi-dev openmpi-bin)"
    "toroid: MPI rendering is skipped: MPI not found (Debian packages libopenmpi-dev, openmpi-bin)")
  return()
endif()
target_sources(toroid PRIVATE ${PROJECT_SOURCE_DIR}/src/cmd/mpi/mpi_render.cpp)
target_link_libraries(toroid PRIVATE MPI::MPI_CXX)
target_compile_definitions(toroid PRIVATE TOROID_HAVE_MPI)
set(TOROID_HAVE_MPI ON)
message(STATUS "toroid: MPI rendering with MPI ${MPI_CXX_VERSION} (${MPIEXEC_EXECUTABLE})")
