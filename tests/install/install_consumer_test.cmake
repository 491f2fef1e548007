# cmake -P script: installs the build tree into a fresh prefix, then
# configures, builds and runs tests/install/consumer against it. Fails (a
# FATAL_ERROR, so a non-zero exit) at the first step that does not work.
#
# -D variables: BUILD_DIR (the locator build tree), WORK_DIR (scratch; wiped
# first), CONSUMER_DIR (the consumer's sources), GENERATOR, BUILD_TYPE,
# CXX_COMPILER, CXX_FLAGS and LINKER_FLAGS (as the locator build used them,
# so that e.g. a sanitizer build's libraries link).

foreach(var BUILD_DIR WORK_DIR CONSUMER_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_consumer_test.cmake: -D${var}=... missing")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})

# Runs a command; a failure ends the test with its output.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${step} failed (${result}):\n${out}\n${err}")
  endif()
  message(STATUS "${step}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
# Exactly the chosen public headers, and nothing of the machinery.
set(public_headers dataset.h dataset_sources.h engine.h engine_info.h
  geometry.h interpolation.h locate_result.h mesh_patch.h profile.h raster.h
  status.h status_or.h tuning_options.h)
file(GLOB_RECURSE installed RELATIVE ${prefix}/include ${prefix}/include/*)
list(SORT installed)
list(TRANSFORM public_headers PREPEND locator/)
if(NOT installed STREQUAL public_headers)
  message(FATAL_ERROR "install: the headers are\n  ${installed}\n"
                      "not the public set\n  ${public_headers}")
endif()
file(GLOB_RECURSE configs ${prefix}/*/locatorConfig.cmake)
if(NOT configs)
  message(FATAL_ERROR "install: no locatorConfig.cmake under ${prefix}")
endif()

run("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR}
    -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
run("build consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run("run consumer" ${WORK_DIR}/build/locator_consumer)
if(NOT last_output MATCHES "locator consumer: ok")
  message(FATAL_ERROR "run consumer: unexpected output:\n${last_output}")
endif()
message(STATUS "${last_output}")
