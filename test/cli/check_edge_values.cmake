cmake_minimum_required(VERSION 3.16)
# `shape_analysis partition --edge-values`: one line "i j value" per edge of the surface, i < j the
# input's vertex indices, every pair once, values in [0, 1]. The input repeats a point (vertex 4
# duplicates vertex 0): its edges are reported with index 0, the first vertex at that position.
#   cmake -DEXE=<tool> -DWORK=<dir> -P check_edge_values.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# An octahedron whose vertex 0 is given twice (0 and 4); faces use both copies.
file(WRITE "${WORK}/octa.off" "OFF\n7 8 0\n1 0 0\n0 1 0\n-1 0 0\n1 0 0\n0 -1 0\n0 0 1\n0 0 -1\n"
  "3 0 1 5\n3 1 2 5\n3 2 4 5\n3 4 3 5\n3 1 0 6\n3 2 1 6\n3 4 2 6\n3 3 4 6\n")
execute_process(COMMAND "${EXE}" partition "${WORK}/octa.off" -n 50 -q --edge-values "${WORK}/e.txt"
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "partition failed (${code}): ${err}")
endif()
file(STRINGS "${WORK}/e.txt" lines)
set(expected "0 1;0 4;0 5;0 6;1 2;1 5;1 6;2 4;2 5;2 6;4 5;4 6")
set(pairs "")
foreach(line ${lines})
  if(NOT line MATCHES "^([0-9]+) ([0-9]+) ([0-9.e+-]+)$")
    message(FATAL_ERROR "bad line '${line}'")
  endif()
  set(i ${CMAKE_MATCH_1})
  set(j ${CMAKE_MATCH_2})
  set(v ${CMAKE_MATCH_3})
  if(NOT i LESS j)
    message(FATAL_ERROR "'${line}': the first index must be the smaller")
  endif()
  if(v LESS 0 OR v GREATER 1)
    message(FATAL_ERROR "'${line}': value outside [0, 1]")
  endif()
  list(APPEND pairs "${i} ${j}")
endforeach()
if(NOT "${pairs}" STREQUAL "${expected}")
  message(FATAL_ERROR "edges ${pairs}, expected ${expected}")
endif()
