# Fails if a tracked file (outside .git) contains the word WORD_A WORD_B
# (case-insensitive): the project describes the code as it is; its history
# is in git log. The word is passed in two halves so that this file and
# tests/CMakeLists.txt do not contain it.
# cmake -DSOURCE_DIR=... -DWORD_A=... -DWORD_B=... -P check_no_history_words.cmake
find_package(Git QUIET)
if(NOT GIT_FOUND OR NOT EXISTS "${SOURCE_DIR}/.git")
  message(STATUS "not a git checkout: nothing to check")
  return()
endif()
execute_process(
  COMMAND ${GIT_EXECUTABLE} -c safe.directory=* -C ${SOURCE_DIR} grep -I -i -n
          "${WORD_A}${WORD_B}"
  OUTPUT_VARIABLE _hits RESULT_VARIABLE _status)
# git grep exits with 1 when nothing matches
if(_status EQUAL 0)
  message(FATAL_ERROR "tracked files mention '${WORD_A}${WORD_B}' (history "
                      "belongs in git log):\n${_hits}")
elseif(NOT _status EQUAL 1)
  message(FATAL_ERROR "git grep failed (exit ${_status})")
endif()
