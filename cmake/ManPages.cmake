# SPDX-License-Identifier: Apache-2.0
#
# The docs and the man(3) pages.
#
# docs/*.md are installed as they are (share/doc/Tracelist).  When pandoc
# is present (as Embree builds its man pages), each reference page
# docs/X.md becomes one man page, tracelist-X(3), and every entry point
# gets a page of its own name that sources it (".so man3/tracelist-X.3",
# the way one GL man page serves glVertex2f, glVertex3f, ...), so
# `man rtNewObject` works once share/man is on MANPATH (it is for the
# default prefixes).  Without pandoc the man pages are skipped with a
# message; nothing else depends on them.
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

find_program(RT_PANDOC pandoc)
if(NOT RT_PANDOC)
  message(STATUS "Tracelist: pandoc not found - man pages switched off")
  return()
endif()
message(STATUS "Tracelist: pandoc found - man pages enabled")

set(rt_man_dir ${PROJECT_BINARY_DIR}/man)
file(GLOB rt_man_inputs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md
  ${PROJECT_SOURCE_DIR}/include/rt/*.h)
add_custom_command(OUTPUT ${rt_man_dir}/man.stamp
  COMMAND ${CMAKE_COMMAND} -DRT_SOURCE_DIR=${PROJECT_SOURCE_DIR} -DRT_MAN_DIR=${rt_man_dir}
          -DRT_PANDOC=${RT_PANDOC} -DRT_VERSION=${PROJECT_VERSION}
          -P ${PROJECT_SOURCE_DIR}/cmake/GenerateManPages.cmake
  DEPENDS ${rt_man_inputs} ${PROJECT_SOURCE_DIR}/cmake/GenerateManPages.cmake
  COMMENT "Generating the man(3) pages with pandoc"
  VERBATIM)
add_custom_target(tracelist_man ALL DEPENDS ${rt_man_dir}/man.stamp)
install(DIRECTORY ${rt_man_dir}/man3 DESTINATION ${CMAKE_INSTALL_MANDIR})
