cmake_minimum_required(VERSION 3.19)
# `shape_analysis points segment` and `points evaluate` end to end: a scanned street with its
# truth (generate), the true locations written as locations.csv (half of them with an empty z), the
# objects segmented from the raw scan (segment, every method), the whole chain in tiles (recognize),
# and the evaluation against the
# truth (evaluate): objects.ply keeps every input point in order with 'object' and 'instance',
# the report has the per-object figures, min-cut's precision and recall are high; bad inputs
# fail with a one-line reason and write nothing.
#   cmake -DEXE=<tool> -DWORK=<dir> -P check_points_segment.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include(${CMAKE_CURRENT_LIST_DIR}/run_tool.cmake)

run_tool(points generate --points 150000 --length 60 --seed 6 -q --output "${WORK}/scene.ply"
         --truth "${WORK}/truth.json" --report "${WORK}/scene.json")
file(READ "${WORK}/scene.json" scene_report)
string(JSON scan_points GET "${scene_report}" number_of_points)

# locations.csv from the truth: x,y,z, every other z left empty (the ground's height is used).
file(READ "${WORK}/truth.json" truth)
string(JSON n LENGTH "${truth}")
if(n LESS 5)
  message(FATAL_ERROR "${n} objects in truth.json")
endif()
set(csv "x,y,z\n")
math(EXPR last "${n} - 1")
foreach(k RANGE ${last})
  string(JSON x GET "${truth}" ${k} location 0)
  string(JSON y GET "${truth}" ${k} location 1)
  string(JSON z GET "${truth}" ${k} location 2)
  math(EXPR odd "${k} % 2")
  if(odd)
    string(APPEND csv "${x},${y},\n")
  else()
    string(APPEND csv "${x},${y},${z}\n")
  endif()
endforeach()
file(WRITE "${WORK}/locations.csv" "${csv}")

foreach(method mincut-auto mincut cc all)
  run_tool(points segment "${WORK}/scene.ply" --locations "${WORK}/locations.csv" --method ${method} -q
           --output "${WORK}/objects_${method}.ply" --report "${WORK}/segment_${method}.json")
  file(READ "${WORK}/segment_${method}.json" report)
  string(JSON objects LENGTH "${report}" objects)
  if(NOT objects EQUAL n)
    message(FATAL_ERROR "${method}: ${objects} objects in the report, ${n} locations")
  endif()
  string(JSON seconds GET "${report}" seconds)
  string(JSON points GET "${report}" objects 0 points)
  string(JSON radius GET "${report}" objects 0 radius)
  string(JSON cut GET "${report}" objects 0 cut)
  string(JSON object_seconds GET "${report}" objects 0 seconds)
  string(JSON total GET "${report}" number_of_points)
  if(NOT total EQUAL scan_points)
    message(FATAL_ERROR "${method}: ${total} points read, the scene has ${scan_points}")
  endif()
  run_tool(points evaluate --truth "${WORK}/truth.json" --locations "${WORK}/locations.csv"
           --objects "${WORK}/objects_${method}.ply" --report "${WORK}/evaluate_${method}.json")
  file(READ "${WORK}/evaluate_${method}.json" evaluation)
  string(JSON recall GET "${evaluation}" segmentation recall)
  string(JSON precision GET "${evaluation}" segmentation precision)
  string(JSON location_recall GET "${evaluation}" localization recall)
  string(JSON classes LENGTH "${evaluation}" segmentation classes)
  message(STATUS "${method}: precision ${precision}, recall ${recall}, ${classes} classes")
  if(NOT location_recall EQUAL 1)
    message(FATAL_ERROR "the true locations found ${location_recall} of the objects")
  endif()
  if(method STREQUAL "mincut-auto" AND (recall LESS 0.7 OR precision LESS 0.7))
    message(FATAL_ERROR "min-cut with the automatic radius: precision ${precision}, recall ${recall}")
  endif()
endforeach()

# The output has every input point, in order, with the input's properties.
file(READ "${WORK}/objects_mincut-auto.ply" header LIMIT 2000)
foreach(p "element vertex ${scan_points}" "property int object" "property int instance" "property uchar ground")
  string(FIND "${header}" "${p}" at)
  if(at LESS 0)
    message(FATAL_ERROR "objects.ply lacks '${p}'")
  endif()
endforeach()

# points recognize: the whole chain in tiles of 20 m on the raw scan; its locations and objects
# evaluated against the truth.
run_tool(points recognize "${WORK}/scene.ply" --tile-size 20 --tile-margin 10 --tile-origin 0,0 -q --output "${WORK}/recognized.ply"
         --locations "${WORK}/found.csv" --report "${WORK}/recognize.json")
file(READ "${WORK}/recognize.json" report)
string(JSON tiles LENGTH "${report}" tiles)
string(JSON found LENGTH "${report}" objects)
string(JSON largest GET "${report}" largest_tile_points)
if(tiles LESS 3 OR found LESS 5 OR NOT largest LESS scan_points)
  message(FATAL_ERROR "points recognize: ${tiles} tiles, ${found} objects, largest tile ${largest} of ${scan_points} points")
endif()
run_tool(points evaluate --truth "${WORK}/truth.json" --locations "${WORK}/found.csv"
         --objects "${WORK}/recognized.ply" --report "${WORK}/evaluate_recognized.json")
file(READ "${WORK}/evaluate_recognized.json" evaluation)
string(JSON recall GET "${evaluation}" segmentation recall)
string(JSON precision GET "${evaluation}" segmentation precision)
string(JSON location_recall GET "${evaluation}" localization recall)
message(STATUS "recognize: ${tiles} tiles, ${found} objects, localization recall ${location_recall}, segmentation precision ${precision}, recall ${recall}")

# The same as LAS (extra bytes 'object', 'instance', 'ground'), read back by points evaluate: the
# same segmentation figures as from the PLY.
run_tool(points recognize "${WORK}/scene.ply" --tile-size 20 --tile-margin 10 --tile-origin 0,0 -q
         --output "${WORK}/recognized.las" --locations "${WORK}/found_las.csv")
run_tool(points evaluate --truth "${WORK}/truth.json" --locations "${WORK}/found_las.csv"
         --objects "${WORK}/recognized.las" --report "${WORK}/evaluate_recognized_las.json")
file(READ "${WORK}/evaluate_recognized_las.json" evaluation)
string(JSON las_recall GET "${evaluation}" segmentation recall)
string(JSON las_precision GET "${evaluation}" segmentation precision)
if(NOT las_recall EQUAL recall OR NOT las_precision EQUAL precision)
  message(FATAL_ERROR "recognized.las: precision ${las_precision}, recall ${las_recall}; from the PLY ${precision}, ${recall}")
endif()
if(location_recall LESS 0.8 OR recall LESS 0.7 OR precision LESS 0.7)
  message(FATAL_ERROR "points recognize: localization recall ${location_recall}, segmentation ${precision} / ${recall}")
endif()

# Bad inputs: one line, non-zero exit, no output.
function(expect_failure message)
  file(REMOVE "${WORK}/bad.ply" "${WORK}/bad.json")
  execute_process(COMMAND "${EXE}" ${ARGN} RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(r EQUAL 0)
    message(FATAL_ERROR "${ARGN}: succeeded")
  endif()
  if(NOT err MATCHES "${message}")
    message(FATAL_ERROR "${ARGN}: expected '${message}' in: ${err}")
  endif()
  if(EXISTS "${WORK}/bad.ply" OR EXISTS "${WORK}/bad.json")
    message(FATAL_ERROR "${ARGN}: an output was written")
  endif()
endfunction()
set(bad --output "${WORK}/bad.ply" --report "${WORK}/bad.json")
file(WRITE "${WORK}/no_header.csv" "1,2,3\n")
file(WRITE "${WORK}/bad_number.csv" "x,y,z\n1,abc,0\n")
file(WRITE "${WORK}/outside.csv" "x,y,z\n100000,0,\n")
expect_failure("header" points segment "${WORK}/scene.ply" --locations "${WORK}/no_header.csv" ${bad})
expect_failure("line 2" points segment "${WORK}/scene.ply" --locations "${WORK}/bad_number.csv" ${bad})
expect_failure("outside" points segment "${WORK}/scene.ply" --locations "${WORK}/outside.csv" ${bad})
expect_failure("radius" points segment "${WORK}/scene.ply" --locations "${WORK}/locations.csv" --method mincut --radius 0 ${bad})
expect_failure("method" points segment "${WORK}/scene.ply" --locations "${WORK}/locations.csv" --method kmeans ${bad})
expect_failure("no such file" points segment "${WORK}/scene.ply" --locations "${WORK}/nothing.csv" ${bad})
expect_failure("PLY or LAS" points segment "${WORK}/scene.ply" --locations "${WORK}/locations.csv" --output "${WORK}/bad.xyz")
expect_failure("object" points evaluate --truth "${WORK}/truth.json" --objects "${WORK}/scene.ply" --report "${WORK}/bad.json")
expect_failure("--locations, --objects" points evaluate --truth "${WORK}/truth.json" --report "${WORK}/bad.json")
expect_failure("no such file" points evaluate --truth "${WORK}/nothing.json" --locations "${WORK}/locations.csv")
expect_failure("tile-size" points recognize "${WORK}/scene.ply" --tile-size 0 ${bad})
expect_failure("tile-margin" points recognize "${WORK}/scene.ply" --tile-margin -1 ${bad})
expect_failure("csv" points recognize "${WORK}/scene.ply" --locations "${WORK}/bad.txt" ${bad})
expect_failure("cannot open|nothing" points recognize "${WORK}/nothing.ply" ${bad})
expect_failure("tile-origin" points recognize "${WORK}/scene.ply" --tile-origin 1 ${bad})

# --interactive on the lamp post at (20.95, 6.09) (seed 6): a background constraint at 4 m up
# takes points out and adds none; a foreground constraint on the sign 2.6 m away adds points and
# takes none out (a cut only shrinks as sink capacities grow, and grows as source ones do).
file(WRITE "${WORK}/lamp.csv" "x,y,z\n20.952,6.087,0.875\n")
file(WRITE "${WORK}/constraints.csv" "kind,x,y,z\nbackground,20.952,6.087,4.875\nforeground,23.543,6.154,2.444\n")
run_tool(points segment "${WORK}/scene.ply" --locations "${WORK}/lamp.csv" --method mincut -q
         --interactive "${WORK}/constraints.csv" -o "${WORK}/interactive.ply" --report "${WORK}/interactive.json")
file(READ "${WORK}/interactive.json" report)
string(JSON steps LENGTH "${report}" steps)
string(JSON first GET "${report}" steps 0 object_points)
string(JSON added1 GET "${report}" steps 1 points_added)
string(JSON removed1 GET "${report}" steps 1 points_removed)
string(JSON added2 GET "${report}" steps 2 points_added)
string(JSON removed2 GET "${report}" steps 2 points_removed)
string(JSON final GET "${report}" objects 0 points)
if(NOT steps EQUAL 3 OR first LESS 50)
  message(FATAL_ERROR "interactive: ${steps} steps, the first object of ${first} points")
endif()
if(NOT added1 EQUAL 0 OR removed1 LESS 1 OR added2 LESS 1 OR NOT removed2 EQUAL 0)
  message(FATAL_ERROR "interactive: background step +${added1} -${removed1}, foreground step +${added2} -${removed2}")
endif()
math(EXPR expected "${first} - ${removed1} + ${added2}")
if(NOT final EQUAL expected)
  message(FATAL_ERROR "interactive: the output object has ${final} points, the steps say ${expected}")
endif()
