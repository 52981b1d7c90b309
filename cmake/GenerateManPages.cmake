# SPDX-License-Identifier: Apache-2.0
#
# cmake -DRT_SOURCE_DIR=... -DRT_MAN_DIR=... -DRT_PANDOC=... -DRT_VERSION=...
#       -P GenerateManPages.cmake
#
# Writes RT_MAN_DIR/man3/tracelist-X.3 for each reference page docs/X.md
# that documents an entry point, and RT_MAN_DIR/man3/<entry point>.3 as a
# ".so" alias for every RTAPI function of rt.h and rtu.h.  An entry point
# belongs to the page that has it in a heading ("### rtNewObject"), else to
# the page its section of the header names ("/* ---- Objects
# (docs/objects.md) ---"); rtu.h's functions default to rtu.md.  A
# function that maps to no page fails the build: every entry point has a
# reference page.
cmake_minimum_required(VERSION 3.16)

file(REMOVE_RECURSE ${RT_MAN_DIR}/man3)
file(MAKE_DIRECTORY ${RT_MAN_DIR}/man3)
file(GLOB pages ${RT_SOURCE_DIR}/docs/*.md)

set(pages_used "")
foreach(header rt.h rtu.h rtu_glut.h)
  file(STRINGS ${RT_SOURCE_DIR}/include/rt/${header} lines)
  if(header STREQUAL "rtu.h")
    set(section_page rtu)
  else()
    set(section_page "")
  endif()
  foreach(line IN LISTS lines)
    if(line MATCHES "^/\\* ----.*docs/([a-z_]+)\\.md")
      set(section_page ${CMAKE_MATCH_1})
    endif()
    if(line MATCHES "^RTAPI .*[ *](rtu?[A-Z][A-Za-z0-9]*)\\(")
      set(fn ${CMAKE_MATCH_1})
      set(page "")
      foreach(md IN LISTS pages)
        file(STRINGS ${md} headings REGEX "^###.*[^A-Za-z0-9]${fn}([^A-Za-z0-9]|$)")
        if(headings)
          get_filename_component(page ${md} NAME_WE)
          break()
        endif()
      endforeach()
      if(NOT page)
        set(page ${section_page})
      endif()
      if(NOT page)
        message(FATAL_ERROR "man pages: no reference page for ${fn}")
      endif()
      file(WRITE ${RT_MAN_DIR}/man3/${fn}.3 ".so man3/tracelist-${page}.3\n")
      list(APPEND pages_used ${page})
      list(APPEND page_functions_${page} ${fn})
    endif()
  endforeach()
endforeach()

# Each page gets the NAME section man(1), whatis and apropos expect
# ("rtGenObjects, rtNewObject, ... - Objects"), then the reference page
# without its title line.
list(REMOVE_DUPLICATES pages_used)
file(MAKE_DIRECTORY ${RT_MAN_DIR}/src)
foreach(page IN LISTS pages_used)
  file(READ ${RT_SOURCE_DIR}/docs/${page}.md text)
  string(REGEX MATCH "^# ([^\n]*)" title_line "${text}")
  set(description "${CMAKE_MATCH_1}")
  string(REGEX REPLACE "^# [^\n]*\n" "" text "${text}")
  string(REPLACE ";" ", " names "${page_functions_${page}}")
  file(WRITE ${RT_MAN_DIR}/src/${page}.md "# NAME\n\n${names} - ${description}\n\n${text}")
  string(TOUPPER "tracelist-${page}" title)
  execute_process(
    COMMAND ${RT_PANDOC} --standalone --from gfm --to man
            --metadata title=${title} --metadata section=3
            --metadata "header=Tracelist Manual" --metadata "footer=Tracelist ${RT_VERSION}"
            -o ${RT_MAN_DIR}/man3/tracelist-${page}.3 ${RT_MAN_DIR}/src/${page}.md
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "man pages: pandoc failed on docs/${page}.md")
  endif()
endforeach()
file(WRITE ${RT_MAN_DIR}/man.stamp "")
