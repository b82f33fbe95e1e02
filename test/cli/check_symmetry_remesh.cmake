cmake_minimum_required(VERSION 3.19)
# `shape_analysis symmetry remesh` and `decimate` end to end on CGAL's cow:
#   remesh: symmetrizes first (the cow is not symmetric), then every vertex and edge mirrored in
#     the report, the input's face count within 5%;
#   remesh of that result: already symmetric (no symmetrization, no mirror point), still mirrored
#     once read back from the OFF file;
#   decimate to a fifth: directly (its connectivity is symmetric), mirrored, within 2 % of the count;
#   decimate --restore from the cow itself: remeshed, restored, mirrored by its pairs;
#   bad face counts, an open mesh and a plane that misses the mesh: refused, nothing written.
#   cmake -DEXE=<tool> -DMESH=<cow.off> -DWORK=<dir> -P check_symmetry_remesh.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include(${CMAKE_CURRENT_LIST_DIR}/run_tool.cmake)

# Fails unless report key `key` compares to `value` by `op` (LESS, GREATER, EQUAL, STREQUAL).
function(expect_report file key op value)
  file(READ "${file}" report)
  string(JSON got GET "${report}" ${key})
  if(NOT got ${op} value)
    message(FATAL_ERROR "${file}: ${key} = ${got}, expected ${op} ${value}")
  endif()
endfunction()

run_tool(symmetry remesh "${MESH}" -q --output "${WORK}/remeshed.off" --report "${WORK}/remeshed.json")
expect_report("${WORK}/remeshed.json" symmetrized STREQUAL ON)
expect_report("${WORK}/remeshed.json" symmetric_edges GREATER 0.999)
expect_report("${WORK}/remeshed.json" paired_vertices GREATER 0.999)
expect_report("${WORK}/remeshed.json" faces GREATER 5513) # 5804 faces, 5%
expect_report("${WORK}/remeshed.json" faces LESS 6095)
expect_report("${WORK}/remeshed.json" seconds GREATER 0)

run_tool(symmetry remesh "${WORK}/remeshed.off" -q --output "${WORK}/again.off" --report "${WORK}/again.json")
expect_report("${WORK}/again.json" symmetrized STREQUAL OFF)
expect_report("${WORK}/again.json" mirror_points EQUAL 0)
expect_report("${WORK}/again.json" symmetric_edges GREATER 0.999)

run_tool(symmetry decimate "${WORK}/remeshed.off" --faces 1160 -q --output "${WORK}/fifth.off"
         --report "${WORK}/fifth.json")
expect_report("${WORK}/fifth.json" remeshed STREQUAL OFF)
expect_report("${WORK}/fifth.json" symmetric_edges GREATER 0.999)
expect_report("${WORK}/fifth.json" faces GREATER 1136)
expect_report("${WORK}/fifth.json" faces LESS 1184)
file(STRINGS "${WORK}/fifth.off" header LIMIT_COUNT 2)
list(GET header 1 counts)
string(REGEX MATCH " [0-9]+ " faces "${counts}")
string(STRIP "${faces}" faces)
file(READ "${WORK}/fifth.json" fifth)
string(JSON reported GET "${fifth}" faces)
if(NOT faces EQUAL reported)
  message(FATAL_ERROR "fifth.off has ${faces} faces, the report ${reported}")
endif()

run_tool(symmetry decimate "${MESH}" --faces 1160 --restore -q --output "${WORK}/restored.off"
         --report "${WORK}/restored.json")
expect_report("${WORK}/restored.json" remeshed STREQUAL ON)
expect_report("${WORK}/restored.json" restored STREQUAL ON)
expect_report("${WORK}/restored.json" symmetric_edges GREATER 0.999)
expect_report("${WORK}/restored.json" copied_side GREATER -2) # 1 or -1, the side copied
expect_report("${WORK}/restored.json" copied_side LESS 2)

set(bad "${WORK}/bad.off;${WORK}/bad.json")
set(write --output "${WORK}/bad.off" --report "${WORK}/bad.json")
expect_tool_failure(2 "positive" "${bad}" symmetry decimate "${MESH}" --faces 0 ${write})
expect_tool_failure(2 "faces" "${bad}" symmetry decimate "${MESH}" ${write})
expect_tool_failure(1 "number_of_faces" "${bad}" symmetry decimate "${MESH}" --faces 100000 ${write})
expect_tool_failure(2 "positive" "${bad}" symmetry remesh "${MESH}" --faces -3 ${write})
expect_tool_failure(1 "does not cross" "${bad}" symmetry remesh "${MESH}" --plane 1,0,0,1000 ${write})
expect_tool_failure(2 "OFF" "${bad}" symmetry remesh "${MESH}" --output "${WORK}/bad.ply")
file(WRITE "${WORK}/open.off" "OFF\n4 3 0\n0 0 0\n1 0 0\n-1 0 0\n0 0 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
expect_tool_failure(1 "not closed" "${bad}" symmetry remesh "${WORK}/open.off" --plane 1,0,0,0 ${write})
