# KseGenerate.cmake: the build-time step of kse_add_statechart (KseBehavior.cmake), run as
#   cmake -DKSE=<kse> -DMODEL=<model.stct> -DNAME=<name> -DOUT=<folder> -DSTAMP=<file>
#         [-DMESSAGES=<dir;dir>] [-DLOGGER=ON] -P KseGenerate.cmake
# Generates the statechart's C++ into OUT with `kse generate --no-activities`, checks that the
# model's class is NAME (the name the build compiles), and touches STAMP. The generator rewrites
# only files whose content changes, so an unchanged statechart is not compiled again.
cmake_minimum_required(VERSION 3.20)

# CMake wraps an error's text at 80 columns; the line a user reads (and greps) is printed whole
function(_kse_stop text)
  message(NOTICE "${text}")
  message(FATAL_ERROR "kse_add_statechart(${NAME}) stopped the build")
endfunction()

set(_arguments generate --quiet --no-activities "${MODEL}" -o "${OUT}")
foreach(_dir IN LISTS MESSAGES)
  list(APPEND _arguments --messages "${_dir}")
endforeach()
if(LOGGER)
  list(APPEND _arguments --logger)
endif()
execute_process(COMMAND "${KSE}" ${_arguments} RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  _kse_stop("kse_add_statechart(${NAME}): kse generate refused ${MODEL} (the lines above say why)")
endif()
if(NOT EXISTS "${OUT}/statecharts/${NAME}/${NAME}.cpp")
  file(GLOB _made LIST_DIRECTORIES true RELATIVE "${OUT}/statecharts" "${OUT}/statecharts/*")
  list(REMOVE_ITEM _made "${NAME}")
  _kse_stop("kse_add_statechart(${NAME}): ${MODEL} holds the statechart '${_made}', not '${NAME}': name the call after the model (kse_add_statechart(${_made} ...))")
endif()
file(TOUCH "${STAMP}")
