# Builds and runs the consumer project of this folder as a downstream user would (cmake -P):
#   MODE=install       cmake --install the library component of BUILD_DIR into WORK_DIR/prefix,
#                      then the consumer with find_package(DGG_VTP_3 CONFIG REQUIRED) from there;
#   MODE=subdirectory  the consumer with add_subdirectory(SOURCE_DIR), FastFloat and MPI made
#                      unfindable, and no build type given: our project must not need the former,
#                      nor build its programs, nor write CMAKE_BUILD_TYPE into the consumer's cache.
# Other variables: SOURCE_DIR (the repository), WORK_DIR (emptied first), MESH, CXX_COMPILER,
# CXX_LAUNCHER (may be empty).
cmake_minimum_required(VERSION 3.21)
foreach(_var MODE SOURCE_DIR WORK_DIR MESH CXX_COMPILER)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_consumer.cmake: ${_var} is not set")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _status)
  if(NOT _status EQUAL 0)
    string(REPLACE ";" " " _command "${ARGN}")
    message(FATAL_ERROR "failed (${_status}): ${_command}")
  endif()
endfunction()

# the value of a cache entry of the consumer's build (empty if absent), and whether it is there
function(cache_entry name value_out present_out)
  file(STRINGS ${WORK_DIR}/build/CMakeCache.txt _lines REGEX "^${name}:[A-Z]+=")
  set(${present_out} FALSE PARENT_SCOPE)
  set(${value_out} "" PARENT_SCOPE)
  if(_lines)
    string(REGEX REPLACE "^${name}:[A-Z]+=" "" _value "${_lines}")
    set(${present_out} TRUE PARENT_SCOPE)
    set(${value_out} "${_value}" PARENT_SCOPE)
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(_configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/DGG_VTP_3_consumer -B ${WORK_DIR}/build
               -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(CXX_LAUNCHER)
  list(APPEND _configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()

if(MODE STREQUAL "install")
  if(NOT DEFINED BUILD_DIR)
    message(FATAL_ERROR "run_consumer.cmake: BUILD_DIR is not set")
  endif()
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix --component DGG_VTP_3)
  run(${_configure} -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
  # the package found must be the one just installed, not the source tree or another copy
  cache_entry(DGG_VTP_3_DIR _found _present)
  file(REAL_PATH ${WORK_DIR}/prefix _prefix)
  file(REAL_PATH "${_found}" _found)
  string(FIND "${_found}" "${_prefix}/" _at)
  if(NOT _at EQUAL 0)
    message(FATAL_ERROR "DGG_VTP_3_DIR is '${_found}', not under the prefix ${_prefix}")
  endif()
  # components, configured only: TBB gives CGAL::TBB_support, an unknown one fails
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/DGG_VTP_3_consumer -B ${WORK_DIR}/build_tbb
      -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCONSUMER_COMPONENTS=TBB)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/DGG_VTP_3_consumer -B ${WORK_DIR}/build_unknown
                          -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCONSUMER_COMPONENTS=No_such_component
                  RESULT_VARIABLE _status OUTPUT_QUIET ERROR_VARIABLE _error)
  if(_status EQUAL 0 OR NOT _error MATCHES "unknown component No_such_component")
    message(FATAL_ERROR "find_package(DGG_VTP_3 COMPONENTS No_such_component) did not fail as it should: ${_error}")
  endif()
elseif(MODE STREQUAL "subdirectory")
  # -O2 by flags, not by build type: the consumer's build type stays the one it was given (none)
  run(${_configure} -DDGG_VTP_3_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_CXX_FLAGS=-O2
      -DCMAKE_DISABLE_FIND_PACKAGE_FastFloat=ON -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON)
  cache_entry(CMAKE_BUILD_TYPE _build_type _present)
  if(NOT _build_type STREQUAL "")
    message(FATAL_ERROR "the consumer's cache holds CMAKE_BUILD_TYPE=${_build_type}; it was given none")
  endif()
  # cli/ is where MPI is searched for and where this option lives: it must not have been read
  cache_entry(DGG_VTP_3_WITH_MPI _value _present)
  if(_present)
    message(FATAL_ERROR "the command-line programs were configured under add_subdirectory()")
  endif()
  foreach(_option CLI EXAMPLES BENCHMARKS TESTING)
    cache_entry(DGG_VTP_3_BUILD_${_option} _value _present)
    if(_value)
      message(FATAL_ERROR "DGG_VTP_3_BUILD_${_option} is '${_value}' under add_subdirectory(): it must default to OFF")
    endif()
  endforeach()
else()
  message(FATAL_ERROR "run_consumer.cmake: MODE must be install or subdirectory, not '${MODE}'")
endif()

run(${CMAKE_COMMAND} --build ${WORK_DIR}/build --target consumer -j2)
run(${WORK_DIR}/build/consumer ${MESH})
