# KseBehavior.cmake: CMake helpers for projects that build behaviours (generated statecharts,
# activities, their own message types) against the KSE runtime.
#
# Included by kse_runtimeConfig.cmake, so after find_package(kse_runtime) these are available:
#
#   kse_protobuf_generate(SOURCES_VAR <var> HEADERS_VAR <var> PROTOS <file>...
#                         OUTPUT_DIR <dir> [PROTO_ROOT <dir>] [IMPORT_DIRS <dir>...])
#       Runs protoc (C++ output) on the given .proto files at build time and returns the paths
#       of the generated .pb.cc / .pb.h in the two variables. Without PROTO_ROOT each file is
#       compiled under its bare name and its <name>.pb.* land in OUTPUT_DIR; with PROTO_ROOT
#       each file is compiled under its path relative to that root (its virtual name, which
#       `import` statements and the generated #includes use) and lands in OUTPUT_DIR/<that path>.
#       IMPORT_DIRS and KSE_RUNTIME_PROTO_DIR are on the import path: the standard messages
#       are imported as "kse/messages/WorldInfo.proto" and so on.
#
#   kse_add_messages(<target> PROTOS <file>... [INCLUDE_PREFIX <prefix>] [IMPORT_DIRS <dir>...])
#       A library <target> holding the generated code of the given .proto files, linked to
#       protobuf; the headers are included as <INCLUDE_PREFIX/Name.pb.h> (default: <Name.pb.h>).
#
#   kse_add_behavior(<target> SOURCES <file>... [LIBRARIES <lib>...])
#       An OBJECT library for generated statecharts and activities, linked to kse::runtime.
#       Statecharts and activities register themselves from static objects
#       (StatechartRegistrar / ActivityRegistrar); a static archive would let the linker drop
#       those objects, an OBJECT library links every one of them into the final executable.
#
#   kse_add_statechart(<name> <model.stct> [MESSAGES <dir>...] [LOGGER])
#       The statechart of a KSE model as an OBJECT library statechart_<name>, linked to
#       kse::runtime. The build generates its C++ from the model (`kse generate --no-activities`
#       into the build tree) and generates it again whenever the model, a .proto of the MESSAGES
#       folders or the kse command changes; an unchanged statechart is not compiled again.
#       <name> is the model's name (its class); a model named otherwise stops the build with
#       the name to use. The activities are the project's own source files (kse_add_behavior, or
#       the folders `kse generate <model> <source-folder>` writes once). MESSAGES: folders of the
#       project's own .proto files the guards read; LOGGER: conditions print their result.
#       The kse command is KSE_EXECUTABLE (a cache variable), else `kse` on the PATH.
#
#   kse_add_activities(<var> <folder>)
#       Every activity folder under <folder> added to the build (the folders `kse generate`
#       and `kse new-behaviour` write: <folder>/<Activity>/ with a CMakeLists.txt making the
#       OBJECT library activity_<Activity>; a folder without CMakeLists.txt, such as common/,
#       is left alone); the targets in <var>, to link into the program directly.
#
#   kse_add_simulator(<target> SOURCE_FOLDER <dir> [LIBRARIES <lib>...])
#       A simulator program <target> (docs/simulation.md): every statechart `kse generate
#       --no-activities` wrote under <dir>/statecharts/ linked in, each activity a stand-in that
#       runs until the script (a conformance case, or the tool's Simulation view) finishes it.
#       It checks conformance cases (--check) or serves a session on standard input (--serve).
#       LIBRARIES: what the statecharts need beyond kse::runtime (a project's own messages).
#
#   Names: activities and statecharts register by name in one registry per program, so each
#   name may be taken once. kse_add_statechart and kse_add_activities claim their names in the
#   configuring project, and so do installed behaviour packages (kse_examples); a name claimed
#   twice stops the configuration naming both (ADR 0029). kse_claim_name(<kind> <name> <origin>)
#   is the check, for a package that brings its own behaviours.

include_guard(GLOBAL)
set(_KSE_GENERATE_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/KseGenerate.cmake)

function(kse_protobuf_generate)
  cmake_parse_arguments(ARG "" "SOURCES_VAR;HEADERS_VAR;OUTPUT_DIR;PROTO_ROOT" "PROTOS;IMPORT_DIRS" ${ARGN})
  if(NOT ARG_SOURCES_VAR OR NOT ARG_HEADERS_VAR OR NOT ARG_OUTPUT_DIR OR NOT ARG_PROTOS)
    message(FATAL_ERROR "kse_protobuf_generate: SOURCES_VAR, HEADERS_VAR, OUTPUT_DIR and PROTOS are required")
  endif()
  if(TARGET protobuf::protoc)
    set(_protoc protobuf::protoc)
  elseif(Protobuf_PROTOC_EXECUTABLE)
    set(_protoc ${Protobuf_PROTOC_EXECUTABLE})
  else()
    message(FATAL_ERROR "kse_protobuf_generate: protoc not found (install protobuf-compiler)")
  endif()

  set(_dirs "")
  if(ARG_PROTO_ROOT)
    get_filename_component(_root ${ARG_PROTO_ROOT} ABSOLUTE)
    list(APPEND _dirs ${_root})
  else()
    foreach(_proto IN LISTS ARG_PROTOS)
      get_filename_component(_abs ${_proto} ABSOLUTE)
      get_filename_component(_dir ${_abs} DIRECTORY)
      list(APPEND _dirs ${_dir})
    endforeach()
  endif()
  foreach(_dir IN LISTS ARG_IMPORT_DIRS)
    get_filename_component(_absdir ${_dir} ABSOLUTE)
    list(APPEND _dirs ${_absdir})
  endforeach()
  if(KSE_RUNTIME_PROTO_DIR AND EXISTS "${KSE_RUNTIME_PROTO_DIR}")
    list(APPEND _dirs ${KSE_RUNTIME_PROTO_DIR})
  endif()
  list(REMOVE_DUPLICATES _dirs)
  set(_includes "")
  foreach(_dir IN LISTS _dirs)
    list(APPEND _includes "-I${_dir}")
  endforeach()

  set(_sources "")
  set(_headers "")
  foreach(_proto IN LISTS ARG_PROTOS)
    get_filename_component(_abs ${_proto} ABSOLUTE)
    get_filename_component(_name ${_abs} NAME_WE)
    if(ARG_PROTO_ROOT)
      file(RELATIVE_PATH _rel ${_root} ${_abs})
      if(_rel MATCHES "^\\.\\.")
        message(FATAL_ERROR "kse_protobuf_generate: ${_abs} is not under PROTO_ROOT ${_root}")
      endif()
      get_filename_component(_reldir ${_rel} DIRECTORY)
      set(_outdir ${ARG_OUTPUT_DIR})
      if(_reldir)
        set(_outdir ${ARG_OUTPUT_DIR}/${_reldir})
      endif()
    else()
      set(_outdir ${ARG_OUTPUT_DIR})
    endif()
    file(MAKE_DIRECTORY ${_outdir})
    set(_cc ${_outdir}/${_name}.pb.cc)
    set(_h ${_outdir}/${_name}.pb.h)
    add_custom_command(
      OUTPUT ${_cc} ${_h}
      COMMAND ${_protoc} --cpp_out=${ARG_OUTPUT_DIR} ${_includes} ${_abs}
      DEPENDS ${_abs} ${_protoc}
      COMMENT "protoc ${_name}.proto"
      VERBATIM)
    list(APPEND _sources ${_cc})
    list(APPEND _headers ${_h})
  endforeach()
  set(${ARG_SOURCES_VAR} ${_sources} PARENT_SCOPE)
  set(${ARG_HEADERS_VAR} ${_headers} PARENT_SCOPE)
endfunction()

function(kse_add_messages target)
  cmake_parse_arguments(ARG "" "INCLUDE_PREFIX" "PROTOS;IMPORT_DIRS" ${ARGN})
  if(NOT ARG_PROTOS)
    message(FATAL_ERROR "kse_add_messages(${target}): PROTOS is required")
  endif()
  set(_base ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  if(ARG_INCLUDE_PREFIX)
    set(_out ${_base}/${ARG_INCLUDE_PREFIX})
  else()
    set(_out ${_base})
  endif()
  kse_protobuf_generate(SOURCES_VAR _srcs HEADERS_VAR _hdrs PROTOS ${ARG_PROTOS}
                        OUTPUT_DIR ${_out} IMPORT_DIRS ${ARG_IMPORT_DIRS})
  add_library(${target} ${_srcs} ${_hdrs})
  target_include_directories(${target} SYSTEM PUBLIC $<BUILD_INTERFACE:${_base}> PRIVATE ${_out})
  target_link_libraries(${target} PUBLIC protobuf::libprotobuf)
  if(TARGET kse::messages)
    target_link_libraries(${target} PUBLIC kse::messages)
  endif()
  target_compile_features(${target} PUBLIC cxx_std_17)
endfunction()

function(kse_add_behavior target)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "kse_add_behavior(${target}): SOURCES is required")
  endif()
  add_library(${target} OBJECT ${ARG_SOURCES})
  target_link_libraries(${target} PUBLIC kse::runtime ${ARG_LIBRARIES})
  target_compile_features(${target} PUBLIC cxx_std_17)
endfunction()

function(kse_claim_name kind name origin)
  get_property(_owner GLOBAL PROPERTY KSE_CLAIMED_${kind}_${name})
  if(_owner AND NOT _owner STREQUAL origin)
    message(FATAL_ERROR "the ${kind} '${name}' of ${origin} has the name of the ${kind} '${name}' of ${_owner}: "
      "${kind} names are global in a program (kse-match registers each name once), rename one "
      "(in its formula, then its folder under activities/ and its registrar's name)")
  endif()
  set_property(GLOBAL PROPERTY KSE_CLAIMED_${kind}_${name} "${origin}")
endfunction()

function(kse_add_activities var folder)
  if(ARGN)
    message(FATAL_ERROR "kse_add_activities(${var} ${folder}): unknown arguments ${ARGN}")
  endif()
  get_filename_component(_root ${folder} ABSOLUTE)
  if(NOT IS_DIRECTORY ${_root})
    message(FATAL_ERROR "kse_add_activities(${var}): no folder ${_root}")
  endif()
  # CONFIGURE_DEPENDS: a new activity folder (kse generate ... --no-statechart) joins at the next build
  file(GLOB _folders LIST_DIRECTORIES true CONFIGURE_DEPENDS ${_root}/*)
  set(_targets "")
  foreach(_dir IN LISTS _folders)
    if(IS_DIRECTORY ${_dir} AND EXISTS ${_dir}/CMakeLists.txt)
      get_filename_component(_name ${_dir} NAME)
      kse_claim_name(activity ${_name} ${_dir})
      add_subdirectory(${_dir} ${CMAKE_CURRENT_BINARY_DIR}/kse_activities/${_name})
      if(NOT TARGET activity_${_name})
        message(FATAL_ERROR "kse_add_activities: ${_dir}/CMakeLists.txt does not make the target activity_${_name}")
      endif()
      list(APPEND _targets activity_${_name})
    endif()
  endforeach()
  set(${var} ${_targets} PARENT_SCOPE)
endfunction()

function(kse_add_statechart name model)
  cmake_parse_arguments(ARG "LOGGER" "" "MESSAGES" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "kse_add_statechart(${name}): unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT name MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "kse_add_statechart(${name}): the name must be the model's name, a C++ identifier")
  endif()
  find_program(KSE_EXECUTABLE kse DOC "the KSE command line (kse generate runs at build time)")
  if(NOT KSE_EXECUTABLE)
    message(FATAL_ERROR "kse_add_statechart(${name}): the kse command was not found: put it on the PATH "
      "or pass -DKSE_EXECUTABLE=/path/to/kse")
  endif()
  get_filename_component(_model ${model} ABSOLUTE)
  if(NOT EXISTS ${_model})
    message(FATAL_ERROR "kse_add_statechart(${name}): no model ${_model}")
  endif()
  kse_claim_name(statechart ${name} ${_model})
  set(_messages "")
  set(_protos "")
  foreach(_dir IN LISTS ARG_MESSAGES)
    get_filename_component(_absdir ${_dir} ABSOLUTE)
    list(APPEND _messages ${_absdir})
    file(GLOB_RECURSE _found CONFIGURE_DEPENDS ${_absdir}/*.proto)
    list(APPEND _protos ${_found})
  endforeach()
  set(_out ${CMAKE_CURRENT_BINARY_DIR}/kse_${name})
  set(_source ${_out}/statecharts/${name}/${name}.cpp)
  set(_stamp ${_out}/${name}.stamp)
  add_custom_command(
    OUTPUT ${_stamp}
    BYPRODUCTS ${_source} ${_out}/statecharts/${name}/${name}.h
    COMMAND ${CMAKE_COMMAND} -DKSE=${KSE_EXECUTABLE} -DMODEL=${_model} -DNAME=${name} -DOUT=${_out}
            -DSTAMP=${_stamp} "-DMESSAGES=${_messages}" -DLOGGER=${ARG_LOGGER} -P ${_KSE_GENERATE_SCRIPT}
    DEPENDS ${_model} ${_protos} ${KSE_EXECUTABLE} ${_KSE_GENERATE_SCRIPT}
    COMMENT "kse generate ${name} from ${model}"
    VERBATIM)
  add_library(statechart_${name} OBJECT ${_source} ${_stamp})
  target_include_directories(statechart_${name} PUBLIC ${_out}/statecharts/${name})
  target_link_libraries(statechart_${name} PUBLIC kse::runtime)
  target_compile_features(statechart_${name} PUBLIC cxx_std_17)
endfunction()

function(kse_add_simulator target)
  cmake_parse_arguments(ARG "" "SOURCE_FOLDER" "LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCE_FOLDER OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "kse_add_simulator(${target}): write kse_add_simulator(<target> SOURCE_FOLDER <dir> [LIBRARIES <lib>...])")
  endif()
  get_filename_component(_root ${ARG_SOURCE_FOLDER} ABSOLUTE)
  file(GLOB _charts LIST_DIRECTORIES true ${_root}/statecharts/*)
  set(_targets "")
  foreach(_dir IN LISTS _charts)
    if(IS_DIRECTORY ${_dir} AND EXISTS ${_dir}/CMakeLists.txt)
      get_filename_component(_name ${_dir} NAME)
      add_subdirectory(${_dir} ${CMAKE_CURRENT_BINARY_DIR}/${target}_statecharts/${_name})
      list(APPEND _targets statechart_${_name})
    endif()
  endforeach()
  if(NOT _targets)
    message(FATAL_ERROR "kse_add_simulator(${target}): no statechart under ${_root}/statecharts (run kse generate --no-activities into ${_root})")
  endif()
  # The statecharts share one precompiled header: protobuf's and the engine's headers are most
  # of their compile time.
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${target}_pch.cpp "")
  add_library(${target}_pch OBJECT ${CMAKE_CURRENT_BINARY_DIR}/${target}_pch.cpp)
  target_link_libraries(${target}_pch PUBLIC kse::runtime ${ARG_LIBRARIES})
  target_precompile_headers(${target}_pch PRIVATE <kse/messages/all.h> <statechart_engine/statechart_engine.h>)
  foreach(_chart IN LISTS _targets)
    target_precompile_headers(${_chart} REUSE_FROM ${target}_pch)
    if(ARG_LIBRARIES)
      target_link_libraries(${_chart} PUBLIC ${ARG_LIBRARIES})
    endif()
  endforeach()
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${target}_main.cpp
    "#include <kse/simulation/Simulator.h>\nint main(int argc, char** argv) { return kse::simulation::RunSimulator(argc, argv); }\n")
  add_executable(${target} ${CMAKE_CURRENT_BINARY_DIR}/${target}_main.cpp)
  target_link_libraries(${target} PRIVATE ${_targets} kse::simulation)
endfunction()
