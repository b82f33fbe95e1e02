# Builds the manual (the `doc` target) and fails when doxygen printed a warning; run by the test
# manual_builds_without_warnings (test/docs/CMakeLists.txt):
#   cmake -DBUILD_DIR=<build directory> -DOUTPUT=<doc_output directory> -P check_manual.cmake
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target doc
                RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "building the doc target failed (${_result})")
endif()
if(NOT EXISTS "${OUTPUT}/html/index.html")
  message(FATAL_ERROR "no manual in ${OUTPUT}/html: are doxygen and python3 installed? (scripts/install_dependencies.sh installs them; re-run cmake after)")
endif()
set(_log "${OUTPUT}/doxygen_warnings.log")
if(NOT EXISTS "${_log}")
  message(FATAL_ERROR "doxygen wrote no warning log (${_log})")
endif()
file(READ "${_log}" _text)
string(STRIP "${_text}" _text)
if(NOT _text STREQUAL "")
  string(REGEX MATCHALL "warning:" _warnings "${_text}")
  list(LENGTH _warnings _count)
  message(FATAL_ERROR "doxygen printed ${_count} warning(s) (${_log}):\n${_text}")
endif()
message(STATUS "The manual builds without doxygen warnings: ${OUTPUT}/html/index.html")
