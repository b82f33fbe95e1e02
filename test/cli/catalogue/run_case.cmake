cmake_minimum_required(VERSION 3.16)
# One case of the bad-input catalogue (cases.txt): runs the tool and checks that it
#   - exits normally with the expected status (no crash, no abort, no hang: 60 s at most); with
#     status 0 (an extreme input that must be processed), only that its output matches the pattern,
#   - says exactly one line on stderr, matching the expected pattern,
#   - leaves its output folder empty (no output, no temporary file; outputs are only written there).
#   cmake -DEXE=<tool> -DARGS="a|b|c" -DEXIT=<n> -DMESSAGE=<regex> -DIN=<inputs> -DOUT=<folder>
#         -DFOUND=<the crash inputs the fuzzers found, kept in found/>
#         -P run_case.cmake
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(resolved "")
foreach(a IN LISTS args)
  string(REPLACE "%IN%" "${IN}" a "${a}")
  string(REPLACE "%OUT%" "${OUT}" a "${a}")
  string(REPLACE "%FOUND%" "${FOUND}" a "${a}")
  list(APPEND resolved "${a}")
endforeach()
execute_process(COMMAND "${EXE}" ${resolved} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 60)
message(STATUS "shape_analysis ${resolved}\nexit ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the tool did not exit normally: ${code}")
endif()
if(NOT code EQUAL EXIT)
  message(FATAL_ERROR "exit status ${code}, expected ${EXIT}")
endif()
if(EXIT EQUAL 0) # an extreme input that must be processed (in time): the pattern is in its output
  if(NOT "${out}${err}" MATCHES "${MESSAGE}")
    message(FATAL_ERROR "the output does not match '${MESSAGE}'")
  endif()
  return()
endif()
string(STRIP "${err}" line)
if(line STREQUAL "" OR line MATCHES "\n")
  message(FATAL_ERROR "expected exactly one line on stderr, got: '${err}'")
endif()
if(NOT line MATCHES "${MESSAGE}")
  message(FATAL_ERROR "stderr '${line}' does not match '${MESSAGE}'")
endif()
file(GLOB_RECURSE left LIST_DIRECTORIES true "${OUT}/*" "${OUT}/.*")
if(left)
  message(FATAL_ERROR "the failed run left files in its output folder: ${left}")
endif()
