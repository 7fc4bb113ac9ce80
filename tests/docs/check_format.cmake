# Fails if a C++ file of the repository differs from what clang-format
# makes of it with the repository's .clang-format (deal.II's style).
# cmake -DCLANG_FORMAT=... -DVERSION=14 -DSOURCE_DIR=... -P check_format.cmake
# Fix a file with: clang-format -i FILE
#
# The repository is formatted by clang-format VERSION; other versions
# format some constructs differently, so with another version (or none)
# the check prints "docs/format skipped: ..." (the test's skip pattern)
# instead of failing on differences that are not the code's.
if(CLANG_FORMAT)
  execute_process(COMMAND ${CLANG_FORMAT} --version
                  OUTPUT_VARIABLE _version_text OUTPUT_STRIP_TRAILING_WHITESPACE)
endif()
if(NOT CLANG_FORMAT OR NOT _version_text MATCHES "version ([0-9.]+)")
  message(STATUS "docs/format skipped: clang-format ${VERSION} is not "
                 "installed (Debian 12: .ci/quickstart.sh test installs it)")
  return()
endif()
set(_found ${CMAKE_MATCH_1})
if(NOT _found MATCHES "^${VERSION}\\.")
  message(STATUS "docs/format skipped: ${CLANG_FORMAT} is version "
                 "${_found}; the repository is formatted by "
                 "clang-format ${VERSION} (Debian 12), whose output other "
                 "versions do not reproduce")
  return()
endif()
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
