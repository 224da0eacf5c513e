# SPDX-License-Identifier: Apache-2.0
# One CTest entry per CppUTest group, found in the test program's own sources
# (every TEST_GROUP(Name) line), so a group that is compiled is always run:
# no hand-kept list to forget one in. The sources are configure dependencies,
# so a new group registers itself on the next build. tests.cpputest_groups
# (tests/registration) checks the result against the programs' own `-lg`.
#
#   glider_add_cpputest_groups(TARGET PREFIX LABELS LABEL... [TIMEOUT S] [STRIP WORD])
#
# adds PREFIX.<Group> running `TARGET -v -sg <Group>`; STRIP drops a leading
# word of the group's name from the test's name (DiagnoseTrend -> diagnose.Trend).
# A test that cannot run here (no privilege, no device) prints a line starting
# "GLIDER-SKIP: why" and returns: CTest then reports its group SKIPPED, never
# passed. The skip covers the whole group's entry, so such a test is a group of its own.
function(glider_add_cpputest_groups target prefix)
  cmake_parse_arguments(ARG "" "STRIP;TIMEOUT" "LABELS" ${ARGN})
  if(NOT ARG_LABELS)
    message(FATAL_ERROR "glider_add_cpputest_groups(${target}): give LABELS (every CTest entry has one)")
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(groups "")
  foreach(source IN LISTS sources)
    get_filename_component(path "${source}" ABSOLUTE BASE_DIR "${source_dir}")
    if(NOT path MATCHES "\\.cpp$")
      continue()
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${path}")
    file(STRINGS "${path}" lines REGEX "^[ \t]*TEST_GROUP(_BASE)?[ \t]*\\(")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*TEST_GROUP(_BASE)?[ \t]*\\([ \t]*([A-Za-z0-9_]+).*$" "\\2" group "${line}")
      list(APPEND groups ${group})
    endforeach()
  endforeach()
  if(NOT groups)
    message(FATAL_ERROR "glider_add_cpputest_groups(${target}): no TEST_GROUP(...) in its sources")
  endif()
  list(REMOVE_DUPLICATES groups)
  foreach(group IN LISTS groups)
    set(name ${group})
    if(ARG_STRIP AND group MATCHES "^${ARG_STRIP}.")
      string(REGEX REPLACE "^${ARG_STRIP}" "" name ${group})
    endif()
    add_test(NAME ${prefix}.${name} COMMAND ${target} -v -sg ${group})
    set_tests_properties(${prefix}.${name} PROPERTIES LABELS "${ARG_LABELS}" SKIP_REGULAR_EXPRESSION "\nGLIDER-SKIP: ")
    if(ARG_TIMEOUT)
      set_tests_properties(${prefix}.${name} PROPERTIES TIMEOUT ${ARG_TIMEOUT})
    endif()
  endforeach()
endfunction()
