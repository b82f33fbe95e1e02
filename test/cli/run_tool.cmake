# run_tool(args...): runs ${EXE} with the arguments, logs its output, fails on a non-zero exit.
# Included by the end-to-end CLI check scripts.
function(run_tool)
  execute_process(COMMAND "${EXE}" ${ARGN} RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${ARGN}\nexit ${r}\nstdout: ${out}\nstderr: ${err}")
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "shape_analysis ${ARGN} failed: ${err}")
  endif()
endfunction()

# expect_tool_failure(<exit code> <message regex> <outputs> args...): runs ${EXE} with the
# arguments, fails unless it exits with that code, says the message on stderr and writes none of
# the outputs (a ;-list, removed first).
function(expect_tool_failure code message outputs)
  file(REMOVE ${outputs})
  execute_process(COMMAND "${EXE}" ${ARGN} RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${ARGN}\nexit ${r}\nstderr: ${err}")
  if(NOT r EQUAL code)
    message(FATAL_ERROR "shape_analysis ${ARGN}: exit ${r}, expected ${code}")
  endif()
  if(NOT err MATCHES "${message}")
    message(FATAL_ERROR "shape_analysis ${ARGN}: expected '${message}' in: ${err}")
  endif()
  foreach(output IN LISTS outputs)
    if(EXISTS "${output}")
      message(FATAL_ERROR "shape_analysis ${ARGN}: ${output} was written")
    endif()
  endforeach()
endfunction()
