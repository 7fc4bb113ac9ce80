# Fails if a C++ file of the repository differs from what clang-format
# makes of it with the repository's .clang-format (deal.II's style).
# cmake -DCLANG_FORMAT=... -DSOURCE_DIR=... -P check_format.cmake
# Fix a file with: clang-format -i FILE
file(GLOB_RECURSE _files
  ${SOURCE_DIR}/include/*.h ${SOURCE_DIR}/source/*.cc
  ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/tests/*.cc
  ${SOURCE_DIR}/bench/*.h ${SOURCE_DIR}/bench/*.cc
  ${SOURCE_DIR}/tutorial/step-*.cc)
set(_unformatted "")
foreach(_file ${_files})
  execute_process(
    COMMAND ${CLANG_FORMAT} --style=file --dry-run -Werror ${_file}
    WORKING_DIRECTORY ${SOURCE_DIR}
    RESULT_VARIABLE _result OUTPUT_QUIET ERROR_QUIET)
  if(NOT _result EQUAL 0)
    file(RELATIVE_PATH _relative ${SOURCE_DIR} ${_file})
    list(APPEND _unformatted ${_relative})
  endif()
endforeach()
list(LENGTH _files _n)
if(_unformatted)
  string(REPLACE ";" "\n  " _list "${_unformatted}")
  message(FATAL_ERROR "not formatted by ${CLANG_FORMAT} (run "
                      "'clang-format -i FILE' on each):\n  ${_list}")
endif()
message(STATUS "${_n} files formatted")
