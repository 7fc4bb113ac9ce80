# Fails if README.md is larger than LIMIT bytes: the README is the
# five-minute entry point; everything else lives in doc/.
# cmake -DREADME=... -DLIMIT=... -P check_readme_size.cmake
file(SIZE "${README}" _size)
if(_size GREATER LIMIT)
  message(FATAL_ERROR "README.md has ${_size} bytes, more than ${LIMIT}: "
                      "move the details to a page in doc/ and link it.")
endif()
message(STATUS "README.md: ${_size} bytes (limit ${LIMIT})")
