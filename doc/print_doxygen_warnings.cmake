# Prints doxygen's warnings (written to a log file by the Doxyfile) after `make doc`.
#   cmake -DLOG=<doxygen_warnings.log> -DMANUAL=<index.html> -P print_doxygen_warnings.cmake
set(_text "")
if(EXISTS "${LOG}")
  file(READ "${LOG}" _text)
endif()
string(STRIP "${_text}" _text)
if(_text STREQUAL "")
  message(STATUS "Manual: ${MANUAL} (no doxygen warnings)")
else()
  string(REGEX MATCHALL "warning:" _warnings "${_text}")
  list(LENGTH _warnings _count)
  message(STATUS "Manual: ${MANUAL}\n${_count} doxygen warning(s), also in ${LOG}:\n${_text}")
endif()
