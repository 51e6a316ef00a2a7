# SPDX-License-Identifier: Apache-2.0
# cmake -DSOURCE=... -DBUILD=... -DPREFIX=... -DLIBDIR=... [-DCC=... -DCXX=...]
#       -P build_shared.cmake
# Builds the torus library alone as a shared library (-DBUILD_SHARED_LIBS=ON,
# -DTOROID_BUILD_RENDERER=OFF: no third-party package) and installs it.
file(REMOVE_RECURSE "${BUILD}" "${PREFIX}")
set(options -DBUILD_SHARED_LIBS=ON -DTOROID_BUILD_RENDERER=OFF -DTOROID_BUILD_TESTS=OFF -DTOROID_BUILD_BENCH=OFF
  -DTOROID_PYTHON=OFF -DTOROID_EMBREE=OFF -DTOROID_INSTALL=ON -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_LIBDIR=${LIBDIR})
if(CC)
  list(APPEND options -DCMAKE_C_COMPILER=${CC} -DCMAKE_CXX_COMPILER=${CXX})
endif()
foreach(step configure build install)
  if(step STREQUAL "configure")
    set(command "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${BUILD}" -G Ninja ${options})
  elseif(step STREQUAL "build")
    set(command "${CMAKE_COMMAND}" --build "${BUILD}")
  else()
    set(command "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}")
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the shared torus library: ${step} failed (${status})")
  endif()
endforeach()
file(GLOB shared "${PREFIX}/${LIBDIR}/libtoroid_torus.so*")
file(GLOB archive "${PREFIX}/${LIBDIR}/libtoroid_torus.a")
if(NOT shared OR archive)
  message(FATAL_ERROR "expected libtoroid_torus.so and no archive in ${PREFIX}/${LIBDIR}")
endif()
