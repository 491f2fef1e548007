# Unity builds: most of the build's CPU time left after the precompiled
# headers (cmake/LocatorPch.cmake) is each translation unit instantiating the
# same templates again (CGAL's triangulation, gtest's, grpc's). A unity group
# compiles several sources as one translation unit, so they are instantiated
# once per group. LOCATOR_UNITY (on by default) turns the groups on; a
# developer iterating on one file may turn it off.
option(LOCATOR_UNITY "Compile the unity groups of locator_unity_groups" ON)

# locator_unity_groups(target ["<source>..." ...]): compiles `target`'s
# sources in unity groups, one translation unit per quoted list, so that the
# headers and template instantiations (CGAL's, gtest's, grpc's) the files of a
# group share are compiled once. Files in one group must not define the same
# name, in anonymous namespaces too; a source in no group is compiled on its
# own. Without a list, all of the target's sources form one group.
function(locator_unity_groups target)
  if(NOT LOCATOR_UNITY)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
  if(ARGC EQUAL 1)
    set_target_properties(${target} PROPERTIES
      UNITY_BUILD_MODE BATCH
      UNITY_BUILD_BATCH_SIZE 0)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD_MODE GROUP)
  set(n 0)
  foreach(group ${ARGN})
    separate_arguments(group UNIX_COMMAND "${group}")
    set_source_files_properties(${group} PROPERTIES
      UNITY_GROUP ${target}_${n})
    math(EXPR n "${n} + 1")
  endforeach()
endfunction()

# locator_unity_by_folder(target): one unity group per source folder of
# `target`, the folders being the library's concerns (for the engine:
# dataset, mesh, cgal, strategies, tuning, surface, tiling, terrain/grid,
# ...). The same rule as above holds within a folder. Generated sources
# (embedded files, whose tables share their names) are compiled on their own.
function(locator_unity_by_folder target)
  if(NOT LOCATOR_UNITY)
    return()
  endif()
  set_target_properties(${target} PROPERTIES
    UNITY_BUILD ON
    UNITY_BUILD_MODE GROUP)
  get_target_property(sources ${target} SOURCES)
  foreach(source ${sources})
    get_source_file_property(generated ${source} TARGET_DIRECTORY ${target}
      GENERATED)
    if(generated)
      set_source_files_properties(${source} TARGET_DIRECTORY ${target}
        PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      continue()
    endif()
    get_filename_component(folder ${source} DIRECTORY)
    string(MAKE_C_IDENTIFIER "${target}_${folder}" group)
    set_source_files_properties(${source} TARGET_DIRECTORY ${target}
      PROPERTIES UNITY_GROUP ${group})
  endforeach()
endfunction()
