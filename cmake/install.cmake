# SPDX-License-Identifier: Apache-2.0
# Install rules: the torus library (headers, archive or shared library, the
# CMake package toroid::torus, pkg-config's toroid-torus) and the toroid
# command. docs/library.md shows how a project uses them.
include(CMakePackageConfigHelpers)

install(TARGETS toroid_torus EXPORT toroidTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT torus
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT torus NAMELINK_COMPONENT torus
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT torus)
file(GLOB toroid_torus_headers ${PROJECT_SOURCE_DIR}/src/toroid/torus/*.h)
# The SIMD batch's kernel, the hole and hull tests and the solver's copies are part of the library's sources, not its interface.
list(FILTER toroid_torus_headers EXCLUDE REGEX "batch_kernel\\.h$")
list(FILTER toroid_torus_headers EXCLUDE REGEX "hole\\.h$")
list(FILTER toroid_torus_headers EXCLUDE REGEX "hull\\.h$")
list(FILTER toroid_torus_headers EXCLUDE REGEX "solver_copies\\.h$")
list(FILTER toroid_torus_headers EXCLUDE REGEX "_test[^/]*\\.h$")
install(FILES ${toroid_torus_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/toroid/torus COMPONENT torus)
# TOROID_HD, which the torus headers use (empty outside nvcc).
install(FILES ${PROJECT_SOURCE_DIR}/src/toroid/math/device.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/toroid/math
  COMPONENT torus)
install(FILES ${PROJECT_SOURCE_DIR}/src/toroid/torus_c.h ${TOROID_VERSION_HEADER}
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/toroid COMPONENT torus)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/toroid COMPONENT torus)

install(EXPORT toroidTargets NAMESPACE toroid:: DESTINATION ${TOROID_CMAKE_DIR} COMPONENT torus)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/toroidConfig.cmake.in
  ${PROJECT_BINARY_DIR}/toroidConfig.cmake INSTALL_DESTINATION ${TOROID_CMAKE_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/toroidConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/toroidConfig.cmake ${PROJECT_BINARY_DIR}/toroidConfigVersion.cmake
  DESTINATION ${TOROID_CMAKE_DIR} COMPONENT torus)

# pkg-config: the file finds the prefix from its own place (${pcfiledir}),
# so that `cmake --install --prefix P` needs no reconfigure. A static
# archive needs the C++ runtime on a C program's link line; a shared
# library brings its own.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  message(FATAL_ERROR "toroid: CMAKE_INSTALL_LIBDIR and CMAKE_INSTALL_INCLUDEDIR must be relative to the prefix")
endif()
file(RELATIVE_PATH toroid_pc_up "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" toroid_pc_up "${toroid_pc_up}")
set(toroid_pc_prefix "\${pcfiledir}/${toroid_pc_up}")
set(toroid_pc_libdir "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
set(toroid_pc_includedir "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
get_target_property(toroid_torus_type toroid_torus TYPE)
if(toroid_torus_type STREQUAL "STATIC_LIBRARY")
  set(toroid_pc_runtime " -lstdc++ -lm")
else()
  set(toroid_pc_runtime "")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/toroid-torus.pc.in ${PROJECT_BINARY_DIR}/toroid-torus.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/toroid-torus.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT torus)

if(TARGET toroid)
  install(TARGETS toroid RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT renderer)
endif()
