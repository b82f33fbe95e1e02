cmake_minimum_required(VERSION 3.19)
# `shape_analysis symmetry detect --rotational` end to end on CGAL's turbine (a disk of revolution
# about x with ten bolt holes): the report's best rotation is 10-fold about x, with its support
# mesh written; the cow has none (an empty list, status 0).
#   cmake -DEXE=<tool> -DMESH=<turbine.off> -DCOW=<cow.off> -DWORK=<dir> -P check_symmetry_rotational.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include(${CMAKE_CURRENT_LIST_DIR}/run_tool.cmake)

run_tool(symmetry detect "${MESH}" -q --rotational --report "${WORK}/detect.json" --output "${WORK}/support.ply")
file(READ "${WORK}/detect.json" report)
string(JSON n LENGTH "${report}" rotations)
if(n LESS 1)
  message(FATAL_ERROR "no rotation in the report")
endif()
string(JSON order GET "${report}" rotations 0 order)
string(JSON kind GET "${report}" rotations 0 kind)
string(JSON ax GET "${report}" rotations 0 axis 0)
string(JSON support GET "${report}" rotations 0 support)
if(NOT order EQUAL 10 OR NOT kind STREQUAL "10-fold")
  message(FATAL_ERROR "best rotation of order ${order} (${kind}), expected 10")
endif()
if(NOT ax GREATER 0.9999 OR NOT support GREATER 0.99)
  message(FATAL_ERROR "best rotation axis x component ${ax}, support ${support}")
endif()
if(NOT EXISTS "${WORK}/support.ply")
  message(FATAL_ERROR "support mesh not written")
endif()

run_tool(symmetry detect "${COW}" -q --rotational --report "${WORK}/cow.json")
file(READ "${WORK}/cow.json" report)
string(JSON n LENGTH "${report}" rotations)
if(NOT n EQUAL 0)
  message(FATAL_ERROR "the cow has ${n} rotations, expected none")
endif()
