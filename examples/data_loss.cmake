# cmake -DPROGRAM=<tool> "-DARGS=<a;@IN@;@OUT@;...>" -DINPUT=<mesh> -DOUT=<file> -P data_loss.cmake
# (INPUT is also the old content of OUT.)
#
# The three ways a tool's write can end badly, none of which may lose a file
# (ARGS name the input @IN@ and the output @OUT@):
# 1. the write fails (a file-size limit of 1 or 2 kB, by the shell's units,
#    as a full disk): exit status
#    2, one line on stderr, OUT exactly as it was, no temporary file left;
# 2. OUT is the input (for a tool with one): the tool reads it whole before it writes, and OUT is
#    then the whole output, the same bytes as written to another name;
# 3. the tool is killed (SIGKILL) at moments spread over its run: OUT is the
#    old file or the whole new one, never a part of it.
# (New policies: under the old CMP0053, "@OUT@" in a quoted argument would
# be replaced by the value of OUT.)
cmake_minimum_required(VERSION 3.16)
get_filename_component(_dir ${OUT} DIRECTORY)
get_filename_component(_base ${OUT} NAME)
function(run_tool in out result_var stderr_var)
  string(REPLACE "@IN@" "${in}" _args "${ARGS}")
  string(REPLACE "@OUT@" "${out}" _args "${_args}")
  execute_process(COMMAND ${ARGN} ${PROGRAM} ${_args} RESULT_VARIABLE _status OUTPUT_QUIET ERROR_VARIABLE _err)
  set(${result_var} "${_status}" PARENT_SCOPE)
  set(${stderr_var} "${_err}" PARENT_SCOPE)
endfunction()

# The whole output, written to another name.
set(_full ${_dir}/full_${_base})
run_tool(${INPUT} ${_full} _status _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "the tool failed on its own: ${_status}: ${_err}")
endif()
file(SHA256 ${_full} _full_hash)
file(SIZE ${_full} _full_size)
if(_full_size LESS 4096)
  message(FATAL_ERROR "the output (${_full_size} bytes) is too small to test a write that fails at 1 or 2 kB")
endif()
file(SHA256 ${INPUT} _old_hash)

# 1. A failed write.
configure_file(${INPUT} ${OUT} COPYONLY)
run_tool(${INPUT} ${OUT} _status _err sh -c "ulimit -f 2 && exec \"$0\" \"$@\"")
file(SHA256 ${OUT} _hash)
file(GLOB _left ${_dir}/.${_base}.tmp.*)
if(NOT _status EQUAL 2 OR NOT _err MATCHES "^[a-z_]+: [^\n]+\n$" OR NOT _hash STREQUAL _old_hash OR _left)
  message(FATAL_ERROR "a failed write: status '${_status}' (2 expected), stderr '${_err}', "
                      "OUT unchanged: ${_hash} vs ${_old_hash}, temporary files left: '${_left}'")
endif()

# 2. OUT = IN, for a tool that reads a file.
if(ARGS MATCHES "@IN@")
  configure_file(${INPUT} ${OUT} COPYONLY)
  run_tool(${OUT} ${OUT} _status _err)
  file(SHA256 ${OUT} _hash)
  if(NOT _status EQUAL 0 OR NOT _hash STREQUAL _full_hash)
    message(FATAL_ERROR "OUT = IN: status '${_status}' (${_err}); OUT is not the whole output")
  endif()
endif()

# 3. Killed part way: the old file or the new one.
set(_outcomes "")
foreach(_delay 0.01 0.03 0.1 0.2 0.3 0.5 0.8 1.2 2 4)
  configure_file(${INPUT} ${OUT} COPYONLY)
  run_tool(${INPUT} ${OUT} _status _err timeout -s KILL ${_delay})
  file(SHA256 ${OUT} _hash)
  if(_hash STREQUAL _old_hash)
    list(APPEND _outcomes old)
  elseif(_hash STREQUAL _full_hash)
    list(APPEND _outcomes new)
  else()
    message(FATAL_ERROR "killed after ${_delay} s: OUT is neither the old file nor the whole output")
  endif()
endforeach()
file(GLOB _left ${_dir}/.${_base}.tmp.*)
if(_left)
  file(REMOVE ${_left})
endif()
file(REMOVE ${_full})
message(STATUS "killed at 10 moments, OUT was: ${_outcomes}")
