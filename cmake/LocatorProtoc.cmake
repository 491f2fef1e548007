# locator_protoc(OUTPUT_VAR <var> LANGUAGE cpp|python OUT_DIR <dir>
#                PROTOS <path relative to proto/>...)
#
# The one protoc invocation of the build: generates the messages and gRPC
# stubs of PROTOS (paths under ${PROJECT_SOURCE_DIR}/proto, as they import
# each other) into OUT_DIR, and sets <var> to the generated files. Every
# generated file depends on every .proto under proto/, so an imported file's
# change regenerates its importers.
find_program(GRPC_CPP_PLUGIN grpc_cpp_plugin REQUIRED)

function(locator_protoc)
  cmake_parse_arguments(ARG "" "OUTPUT_VAR;LANGUAGE;OUT_DIR" "PROTOS" ${ARGN})
  set(proto_root ${PROJECT_SOURCE_DIR}/proto)
  file(GLOB_RECURSE all_protos CONFIGURE_DEPENDS ${proto_root}/*.proto)
  set(outputs)
  set(sources)
  foreach(proto ${ARG_PROTOS})
    string(REGEX REPLACE "\\.proto$" "" stem ${proto})
    list(APPEND sources ${proto_root}/${proto})
    if(ARG_LANGUAGE STREQUAL "cpp")
      list(APPEND outputs ${ARG_OUT_DIR}/${stem}.pb.cc ${ARG_OUT_DIR}/${stem}.pb.h
           ${ARG_OUT_DIR}/${stem}.grpc.pb.cc ${ARG_OUT_DIR}/${stem}.grpc.pb.h)
    elseif(ARG_LANGUAGE STREQUAL "python")
      list(APPEND outputs ${ARG_OUT_DIR}/${stem}_pb2.py
           ${ARG_OUT_DIR}/${stem}_pb2_grpc.py)
    else()
      message(FATAL_ERROR "locator_protoc: LANGUAGE must be cpp or python")
    endif()
  endforeach()
  if(ARG_LANGUAGE STREQUAL "cpp")
    set(flags --cpp_out=${ARG_OUT_DIR} --grpc_out=${ARG_OUT_DIR}
        --plugin=protoc-gen-grpc=${GRPC_CPP_PLUGIN})
  else()
    find_program(GRPC_PYTHON_PLUGIN grpc_python_plugin REQUIRED)
    set(flags --python_out=${ARG_OUT_DIR} --grpc_python_out=${ARG_OUT_DIR}
        --plugin=protoc-gen-grpc_python=${GRPC_PYTHON_PLUGIN})
  endif()
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${ARG_OUT_DIR}
    COMMAND ${Protobuf_PROTOC_EXECUTABLE} --proto_path=${proto_root} ${flags}
      ${sources}
    DEPENDS ${all_protos}
    COMMENT "Generating ${ARG_LANGUAGE} code for ${ARG_PROTOS}")
  set(${ARG_OUTPUT_VAR} ${outputs} PARENT_SCOPE)
endfunction()
