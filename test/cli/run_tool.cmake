# run_tool(args...): runs ${EXE} with the arguments, logs its output, fails on a non-zero exit.
# Included by the end-to-end CLI check scripts.
function(run_tool)
  execute_process(COMMAND "${EXE}" ${ARGN} RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${ARGN}\nexit ${r}\nstdout: ${out}\nstderr: ${err}")
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "shape_analysis ${ARGN} failed: ${err}")
  endif()
endfunction()
