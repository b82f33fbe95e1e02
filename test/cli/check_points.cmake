cmake_minimum_required(VERSION 3.19)
# `shape_analysis points` end to end: a scanned street (scene), its background removed
# (background), its objects located and evaluated against the scene's ground truth (locate): the
# report's recall and precision are above 0.3 and every output is written.
#   cmake -DEXE=<tool> -DWORK=<dir> -P check_points.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include(${CMAKE_CURRENT_LIST_DIR}/run_tool.cmake)

run_tool(points scene --points 150000 --length 100 --seed 5 -q --output "${WORK}/scene.ply"
         --objects "${WORK}/objects.json")
run_tool(points background "${WORK}/scene.ply" -q --output "${WORK}/foreground.ply" --report "${WORK}/background.json")
run_tool(points locate "${WORK}/foreground.ply" -q --truth "${WORK}/objects.json" --output "${WORK}/locations.json"
         --report "${WORK}/locate.json")
file(READ "${WORK}/locate.json" report)
string(JSON recall GET "${report}" evaluation recall)
string(JSON precision GET "${report}" evaluation precision)
string(JSON objects GET "${report}" evaluation objects)
if(objects LESS 10)
  message(FATAL_ERROR "only ${objects} true objects read from objects.json")
endif()
if(NOT recall GREATER 0.3 OR NOT precision GREATER 0.3)
  message(FATAL_ERROR "localization recall ${recall}, precision ${precision}: expected above 0.3")
endif()
run_tool(points locate "${WORK}/foreground.ply" -q --method mean-shift --truth "${WORK}/objects.json"
         --output "${WORK}/locations_mean_shift.json" --report "${WORK}/locate_mean_shift.json")
file(READ "${WORK}/locate_mean_shift.json" report)
string(JSON recall GET "${report}" evaluation recall)
if(NOT recall GREATER 0.3)
  message(FATAL_ERROR "mean-shift localization recall ${recall}: expected above 0.3")
endif()
file(READ "${WORK}/locations.json" locations)
string(JSON n LENGTH "${locations}")
if(n LESS 5)
  message(FATAL_ERROR "${n} locations")
endif()
