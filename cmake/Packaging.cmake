# SPDX-License-Identifier: Apache-2.0
#
# What `cmake --install` puts in the prefix: the libraries, the headers
# (with the generated rt_version.h), the CMake package (find_package),
# and two pkg-config files: tracelist.pc (the core) and tracelist-rtu.pc
# (the utility library, which Requires: tracelist), as GLU's glu.pc
# requires gl.pc.
install(TARGETS tracelist tracelist_static tracelist_rtu EXPORT TracelistTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/rt DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  PATTERN "*.in" EXCLUDE)
install(FILES ${RT_GENERATED_INCLUDE_DIR}/rt/rt_version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rt)
install(EXPORT TracelistTargets NAMESPACE Tracelist::
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tracelist)
configure_package_config_file(cmake/TracelistConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TracelistConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tracelist)
# 0.x minor versions are incompatible with each other (the soname says so
# too); from 1.0 on, the same major version is compatible.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(rt_compatibility SameMinorVersion)
else()
  set(rt_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TracelistConfigVersion.cmake
  COMPATIBILITY ${rt_compatibility})
install(FILES ${PROJECT_BINARY_DIR}/TracelistConfig.cmake
  ${PROJECT_BINARY_DIR}/TracelistConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Tracelist)

# The .pc files find their prefix from their own location, so an installed
# tree can be moved (and the install test can use a scratch prefix).
file(RELATIVE_PATH RT_PC_TO_PREFIX "${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig" "${CMAKE_INSTALL_PREFIX}")
foreach(pc tracelist tracelist-rtu)
  configure_file(cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()

# The licence and the README beside the docs.
install(FILES LICENSE README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
