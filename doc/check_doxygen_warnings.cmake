# Fails the 'doc' target if doxygen wrote any warning to LOG.
if(EXISTS ${LOG})
  file(READ ${LOG} _warnings)
  string(STRIP "${_warnings}" _warnings)
  if(NOT _warnings STREQUAL "")
    message(FATAL_ERROR "doxygen warnings (${LOG}):\n${_warnings}")
  endif()
endif()
message(STATUS "doxygen: no warnings")
