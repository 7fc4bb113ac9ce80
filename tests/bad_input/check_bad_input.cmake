# Run hemicontact on a broken parameter file and check that it fails the
# way the file's header says:
#   # expect-exit: N
#   # expect-message: REGEX      (matched against standard error)
#   # run-with: ARGUMENT         (optional: run with this instead of the file)
# and that the message is one clean paragraph (no stack trace, no deal.II
# exception banner), and that an input error (exit 2) leaves the output
# of an earlier run intact.
file(STRINGS ${PRM} _lines)
foreach(_line ${_lines})
  if(_line MATCHES "^# expect-exit: *([0-9]+)")
    set(_exit ${CMAKE_MATCH_1})
  elseif(_line MATCHES "^# expect-message: *(.*)$")
    set(_message "${CMAKE_MATCH_1}")
  elseif(_line MATCHES "^# run-with: *(.*)$")
    set(_argument "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT DEFINED _exit OR NOT DEFINED _message)
  message(FATAL_ERROR "${PRM}: missing '# expect-exit:' or '# expect-message:' header")
endif()

get_filename_component(_name ${PRM} NAME_WE)
set(_dir ${WORKDIR}/${_name})
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
# output of an earlier run in the default output directory must survive
file(WRITE ${_dir}/output/steps.csv "an earlier run\n")
# @BAD_INPUT_DIR@ in the file (e.g. a mesh file shipped in bad_input/meshes)
# stands for the directory of the corpus: the run reads a copy with it
# replaced
file(READ ${PRM} _text)
set(_file ${PRM})
if(_text MATCHES "@BAD_INPUT_DIR@")
  get_filename_component(_corpus ${PRM} DIRECTORY)
  string(REPLACE "@BAD_INPUT_DIR@" "${_corpus}" _text "${_text}")
  set(_file ${_dir}/run.prm)
  file(WRITE ${_file} "${_text}")
endif()
if(NOT DEFINED _argument)
  set(_argument ${_file})
endif()
execute_process(COMMAND ${EXE} ${_argument}
  WORKING_DIRECTORY ${_dir}
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err
  TIMEOUT 120)

if(NOT "${_rc}" STREQUAL "${_exit}")
  message(FATAL_ERROR "expected exit code ${_exit}, got '${_rc}'.\nstderr:\n${_err}\nstdout:\n${_out}")
endif()
if(NOT _err MATCHES "${_message}")
  message(FATAL_ERROR "stderr does not match '${_message}':\n${_err}")
endif()
if(_err MATCHES "Stacktrace|An error occurred in line|-------")
  message(FATAL_ERROR "the message is not a clean paragraph:\n${_err}")
endif()
# an input error is found before anything is written
file(READ ${_dir}/output/steps.csv _previous)
if(_exit EQUAL 2 AND NOT _previous STREQUAL "an earlier run\n")
  message(FATAL_ERROR "the failed run changed output/steps.csv of an earlier run")
endif()
message(STATUS "ok: exit ${_rc}: ${_err}")
