# SPDX-License-Identifier: Apache-2.0
# cmake -DBUILD=... -DPREFIX=... -DCOMPONENT=... -DLIBDIR=... -P install.cmake:
# a fresh install of one component of a build folder, for the consumer tests.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}" --component "${COMPONENT}"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD} --component ${COMPONENT} failed: ${status}")
endif()
foreach(file include/toroid/torus_c.h include/toroid/torus/intersect.h include/toroid/version.h
    ${LIBDIR}/cmake/toroid/toroidConfig.cmake ${LIBDIR}/pkgconfig/toroid-torus.pc)
  if(NOT EXISTS "${PREFIX}/${file}")
    message(FATAL_ERROR "the install has no ${file}")
  endif()
endforeach()
