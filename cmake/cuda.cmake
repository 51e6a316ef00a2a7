# SPDX-License-Identifier: Apache-2.0
# The CUDA batch (cuda/: toroid::torus_cuda, its tests and tools/gpu-check.sh's
# program). TOROID_CUDA: AUTO builds it when CMake finds a CUDA compiler
# (check_language: CUDACXX, CMAKE_CUDA_COMPILER, or nvcc on PATH), ON
# requires one, OFF leaves it out. Off in sanitized builds. Sets
# TOROID_HAVE_CUDA.
include(${PROJECT_SOURCE_DIR}/cmake/optional_feature.cmake)
set(TOROID_CUDA AUTO CACHE STRING "Build the CUDA batch (cuda/): ON, OFF, or AUTO (when a CUDA compiler is found)")
set_property(CACHE TOROID_CUDA PROPERTY STRINGS AUTO ON OFF)
option(TOROID_CUDA_FMAD "Let nvcc contract multiply-adds in the kernel (OFF: --fmad=false, the CPU's operations)" OFF)
set(TOROID_HAVE_CUDA OFF)
toroid_feature_mode(TOROID_CUDA toroid_cuda_mode)
if(toroid_cuda_mode STREQUAL "OFF")
  return()
endif()
# The sanitizers instrument host code only, and the CUDA runtime is not
# instrumented.
toroid_sanitized_build(toroid_sanitized)
if(toroid_sanitized)
  toroid_feature_unavailable(${toroid_cuda_mode}
    "TOROID_CUDA=ON cannot be combined with a sanitized build"
    "toroid: the CUDA batch is skipped in a sanitized build")
  return()
endif()
include(CheckLanguage)
check_language(CUDA)
if(NOT CMAKE_CUDA_COMPILER)
  toroid_feature_unavailable(${toroid_cuda_mode}
    "TOROID_CUDA=ON, but no CUDA compiler was found: put nvcc on PATH or pass -DCMAKE_CUDA_COMPILER=/usr/local/cuda/bin/nvcc"
    "toroid: the CUDA batch is skipped: no CUDA compiler found (nvcc on PATH, or CMAKE_CUDA_COMPILER)")
  return()
endif()
# sm_90 (H100, H200) unless the user chose: one architecture keeps nvcc's
# time small in CI.
if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
  set(CMAKE_CUDA_ARCHITECTURES 90)
endif()
enable_language(CUDA)
# CMake 3.25 knows no C++20 flag for nvcc (its list stops at C++17): name it
# where it is missing (nvcc 12 and later take -std=c++20).
if(NOT CMAKE_CUDA20_STANDARD_COMPILE_OPTION AND CMAKE_CUDA_COMPILER_VERSION VERSION_GREATER_EQUAL 12)
  set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION -std=c++20)
  set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION -std=c++20)
endif()
find_package(CUDAToolkit QUIET)
if(NOT CUDAToolkit_FOUND)
  toroid_feature_unavailable(${toroid_cuda_mode}
    "TOROID_CUDA=ON, but the CUDA toolkit of ${CMAKE_CUDA_COMPILER} was not found"
    "toroid: the CUDA batch is skipped: CUDA toolkit not found")
  return()
endif()
add_subdirectory(${PROJECT_SOURCE_DIR}/cuda ${PROJECT_BINARY_DIR}/cuda)
set(TOROID_HAVE_CUDA ON)
message(STATUS "toroid: CUDA batch with nvcc ${CMAKE_CUDA_COMPILER_VERSION}, architectures ${CMAKE_CUDA_ARCHITECTURES}")
