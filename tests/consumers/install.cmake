# SPDX-License-Identifier: Apache-2.0
# cmake -DBUILD=... -DPREFIX=... "-DCOMPONENTS=torus;embree" -DLIBDIR=... -P install.cmake:
# a fresh install of some components of a build folder, for the consumer tests.
file(REMOVE_RECURSE "${PREFIX}")
foreach(component ${COMPONENTS})
  execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}" --component "${component}"
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "cmake --install ${BUILD} --component ${component} failed: ${status}")
  endif()
endforeach()
foreach(file include/toroid/torus_c.h include/toroid/torus/intersect.h include/toroid/version.h
    ${LIBDIR}/cmake/toroid/toroidConfig.cmake ${LIBDIR}/pkgconfig/toroid-torus.pc)
  if(NOT EXISTS "${PREFIX}/${file}")
    message(FATAL_ERROR "the install has no ${file}")
  endif()
endforeach()
