# Precompiled headers (LOCATOR_PCH, on by default).
#
# Most of the build's CPU time is the compiler front end parsing the same
# headers again in every translation unit: CGAL's constrained triangulation
# (about 8 of the 10 s of a small server/core file) and, in every test,
# gtest, gmock and grpcpp (about 4 s). Each group of targets compiled with the
# same flags shares one precompiled header, made once by an anchor target:
#
#   locator_core               CGAL               server/core, server/bench
#   locator_core_test_support  CGAL, gtest/gmock  tests/core
#   locator_test_pch           gtest/gmock, grpcpp, locator.v1 stubs
#                                                 every other test directory
#
# A target may reuse an anchor's header only when it is compiled with the
# same sanitizer flags and defines no macro the anchor defines to another
# value (clang rejects the header otherwise; gcc silently falls back to
# parsing). Extra macros are fine. Anchors therefore carry no macros of their
# own, and tests/core, which ThreadSanitizer instruments, has its own anchor.
#
# With ccache, headers are only cached under the sloppiness deploy/test.sh
# sets (pch_defines,time_macros).
option(LOCATOR_PCH "Precompile CGAL, gtest, gmock and grpcpp headers" ON)

set(LOCATOR_CGAL_PCH_HEADERS
  <CGAL/Constrained_Delaunay_triangulation_2.h>
  <CGAL/Constrained_triangulation_face_base_2.h>
  <CGAL/Constrained_triangulation_plus_2.h>
  <CGAL/Exact_predicates_inexact_constructions_kernel.h>
  <CGAL/Triangulation_data_structure_2.h>
  <CGAL/Triangulation_face_base_with_info_2.h>
  <CGAL/Triangulation_vertex_base_with_info_2.h>)
set(LOCATOR_TEST_PCH_HEADERS <gmock/gmock.h> <gtest/gtest.h>)

# locator_precompile(ANCHOR HEADERS <header>... [REQUIRES <library>...]):
# ANCHOR precompiles the headers for itself and for the targets that reuse
# them. REQUIRES names the libraries whose include directories and macros
# the headers need; ANCHOR and every reuser link them.
function(locator_precompile anchor)
  cmake_parse_arguments(ARG "" "" "HEADERS;REQUIRES" ${ARGN})
  if(LOCATOR_PCH)
    target_precompile_headers(${anchor} PRIVATE ${ARG_HEADERS})
    target_link_libraries(${anchor} PRIVATE ${ARG_REQUIRES})
    set_target_properties(${anchor} PROPERTIES
      LOCATOR_PCH_REQUIRES "${ARG_REQUIRES}")
  endif()
endfunction()

# locator_reuse_pch(TARGET ANCHOR): TARGET compiles with ANCHOR's header, and
# links what the header requires, so that its compile is a superset of the
# anchor's (the header's precondition) even where it does not use them.
function(locator_reuse_pch target anchor)
  if(LOCATOR_PCH)
    target_precompile_headers(${target} REUSE_FROM ${anchor})
    get_target_property(requires ${anchor} LOCATOR_PCH_REQUIRES)
    target_link_libraries(${target} PRIVATE ${requires})
  endif()
endfunction()

# locator_reuse_pch_in_directory(ANCHOR): every C++ target defined so far in
# the calling directory, but ANCHOR, compiles with ANCHOR's header.
function(locator_reuse_pch_in_directory anchor)
  if(NOT LOCATOR_PCH)
    return()
  endif()
  get_property(targets DIRECTORY PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    if(NOT target STREQUAL anchor AND type MATCHES
       "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY)$")
      locator_reuse_pch(${target} ${anchor})
    endif()
  endforeach()
endfunction()
