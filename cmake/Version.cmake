# SPDX-License-Identifier: Apache-2.0
#
# The generated version header and the soname.
#
# include/rt/rt_version.h.in -> <build>/include/rt/rt_version.h, on the
# include path of every target that links the libraries (and installed
# beside rt.h, which includes it).
#
# The soname tracks the minor version while the major version is 0:
# 0.1 and 0.2 are declared incompatible, so they must not share
# libtracelist.so.0 (the same rule as Semantic Versioning's 0.y.z).
set(RT_GENERATED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
configure_file(${PROJECT_SOURCE_DIR}/include/rt/rt_version.h.in
  ${RT_GENERATED_INCLUDE_DIR}/rt/rt_version.h @ONLY)
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(RT_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
else()
  set(RT_SOVERSION ${PROJECT_VERSION_MAJOR})
endif()
