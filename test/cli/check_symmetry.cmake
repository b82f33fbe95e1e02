cmake_minimum_required(VERSION 3.19)
# `shape_analysis symmetry` end to end on CGAL's triceratops (mirror-symmetric about z = 0):
#   detect: the report's best plane is z = 0 with a small score;
#   symmetrize: the symmetrized mesh has the input's vertex and face counts, the map one line per
#     vertex, the report a lower symmetry error after than before;
#   enhance: from the symmetrized mesh (no solve), amount -1 written with the same counts;
#   transfer: on an octahedron coloured red (x > 0), blue (x < 0) and green (x = 0), copying across
#     x = 0 recolours exactly the one vertex of the negative side.
#   cmake -DEXE=<tool> -DMESH=<triceratops.off> -DWORK=<dir> -P check_symmetry.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include(${CMAKE_CURRENT_LIST_DIR}/run_tool.cmake)

run_tool(symmetry detect "${MESH}" -q --report "${WORK}/detect.json" --output "${WORK}/support.ply")
file(READ "${WORK}/detect.json" report)
string(JSON n LENGTH "${report}" planes)
if(n LESS 1)
  message(FATAL_ERROR "no plane in the report")
endif()
string(JSON nz GET "${report}" planes 0 normal 2)
string(JSON score GET "${report}" planes 0 score)
string(JSON support GET "${report}" planes 0 support)
string(JSON seconds GET "${report}" seconds)
if(NOT (nz GREATER 0.999 OR nz LESS -0.999))
  message(FATAL_ERROR "best plane normal z component ${nz}, expected +-1 (the plane z = 0)")
endif()
if(NOT score LESS 0.001 OR NOT support GREATER 0.9)
  message(FATAL_ERROR "best plane score ${score} / support ${support}")
endif()
if(NOT EXISTS "${WORK}/support.ply")
  message(FATAL_ERROR "support mesh not written")
endif()

run_tool(symmetry symmetrize "${MESH}" -q --output "${WORK}/sym.off" --map "${WORK}/map.txt"
         --report "${WORK}/sym.json")
file(STRINGS "${WORK}/sym.off" header LIMIT_COUNT 2)
file(STRINGS "${MESH}" input_header LIMIT_COUNT 2)
if(NOT header STREQUAL input_header)
  message(FATAL_ERROR "symmetrized mesh header '${header}', expected '${input_header}'")
endif()
file(STRINGS "${WORK}/map.txt" map)
list(LENGTH map n_map)
list(GET input_header 1 counts)
string(REGEX MATCH "^[0-9]+" n_vertices "${counts}")
math(EXPR expected "${n_vertices} + 3")
if(NOT n_map EQUAL expected)
  message(FATAL_ERROR "map has ${n_map} lines, expected ${expected} (3 comment lines, one per vertex)")
endif()
file(READ "${WORK}/sym.json" sym)
string(JSON before GET "${sym}" symmetry_error_before)
string(JSON after GET "${sym}" symmetry_error_after)
string(JSON distortion GET "${sym}" distortion)
string(JSON seconds GET "${sym}" seconds)
if(NOT after LESS before)
  message(FATAL_ERROR "symmetry error ${before} -> ${after}: not lower")
endif()

run_tool(symmetry enhance "${MESH}" -q --symmetric "${WORK}/sym.off" --amount -1 --output "${WORK}/enhanced.off")
file(STRINGS "${WORK}/enhanced.off" enhanced_header LIMIT_COUNT 2)
if(NOT enhanced_header STREQUAL input_header)
  message(FATAL_ERROR "enhanced mesh header '${enhanced_header}'")
endif()

file(WRITE "${WORK}/octahedron.ply" "ply
format ascii 1.0
element vertex 6
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 8
property list uchar int vertex_indices
end_header
1 0 0 255 0 0
-1 0 0 0 0 255
0 1 0 0 255 0
0 -1 0 0 255 0
0 0 1 0 255 0
0 0 -1 0 255 0
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
")
run_tool(symmetry transfer "${WORK}/octahedron.ply" -q --plane 1,0,0,0 --output "${WORK}/transferred.ply"
         --report "${WORK}/transfer.json")
file(READ "${WORK}/transfer.json" transfer)
string(JSON changed GET "${transfer}" vertices_changed)
if(NOT changed EQUAL 1)
  message(FATAL_ERROR "${changed} vertices recoloured, expected 1 (the blue one)")
endif()

# transfer --symmetric: the input's blue vertex is at x = -0.6 (asymmetric); through the symmetric
# map of the symmetrized octahedron (x = -1) its mirror point is the red vertex itself, so it turns
# exactly red; through the input's own map its mirror point (0.6, 0, 0) is off the surface and its
# colour a blend of the red and green vertices.
file(READ "${WORK}/octahedron.ply" octa)
string(REPLACE "-1 0 0 0 0 255" "-0.6 0 0 0 0 255" warped "${octa}")
file(WRITE "${WORK}/warped.ply" "${warped}")
file(WRITE "${WORK}/symmetrized.off" "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
  "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n")
# The colour (hex rrggbb) of vertex `index` of a PLY written by the tool (binary, x y z doubles and
# red green blue uchars per vertex).
function(vertex_colour file index out)
  file(READ "${file}" hex HEX)
  string(FIND "${hex}" "656e645f6865616465720a" at) # "end_header\n"
  math(EXPR at "${at} + 22 + 2 * (${index} * 27 + 24)")
  string(SUBSTRING "${hex}" ${at} 6 colour)
  set(${out} "${colour}" PARENT_SCOPE)
endfunction()
run_tool(symmetry transfer "${WORK}/warped.ply" -q --plane 1,0,0,0 --symmetric "${WORK}/symmetrized.off"
         --output "${WORK}/through_symmetric.ply" --report "${WORK}/through_symmetric.json")
vertex_colour("${WORK}/through_symmetric.ply" 1 through_symmetric)
if(NOT through_symmetric STREQUAL "ff0000")
  message(FATAL_ERROR "through the symmetrized mesh's map the vertex became ${through_symmetric}, expected ff0000")
endif()
run_tool(symmetry transfer "${WORK}/warped.ply" -q --plane 1,0,0,0 --output "${WORK}/own_map.ply")
vertex_colour("${WORK}/own_map.ply" 1 own)
if(own STREQUAL "ff0000")
  message(FATAL_ERROR "through the input's own map the vertex is pure red too: the test shows nothing")
endif()

# symmetrize --detected-planes 2: the triceratops' two best planes (z = 0 global, a partial one),
# each with its support, symmetrized together; --plane repeated: both planes reported.
run_tool(symmetry symmetrize "${MESH}" -q --detected-planes 2 --output "${WORK}/two.off" --report "${WORK}/two.json")
file(READ "${WORK}/two.json" two)
string(JSON n LENGTH "${two}" planes)
string(JSON nz GET "${two}" planes 0 normal 2)
string(JSON support0 GET "${two}" planes 0 support)
string(JSON support1 GET "${two}" planes 1 support)
string(JSON before GET "${two}" symmetry_error_before)
string(JSON after GET "${two}" symmetry_error_after)
if(NOT n EQUAL 2 OR NOT (nz GREATER 0.999 OR nz LESS -0.999) OR support0 LESS 0.9 OR NOT support1 LESS support0)
  message(FATAL_ERROR "--detected-planes 2: ${n} planes, first normal z ${nz}, supports ${support0} ${support1}")
endif()
if(NOT after LESS before)
  message(FATAL_ERROR "--detected-planes 2: symmetry error ${before} -> ${after}")
endif()
string(JSON angle GET "${two}" regularization maximum_angle)
string(JSON dropped GET "${two}" regularization dropped)
if(NOT angle EQUAL 2 OR NOT dropped EQUAL 0)
  message(FATAL_ERROR "--detected-planes 2: regularized within ${angle} degrees, ${dropped} dropped (expected 2, 0)")
endif()
# --regularize with planes given: the second plane, 1.15 degrees from perpendicular to the first,
# is made perpendicular (its normal's z exactly 0); without --regularize it is kept as given.
run_tool(symmetry symmetrize "${MESH}" -q --plane 0,0,1,0 --plane 1,0,0.02,0 --regularize 2 --iterations 2
         --output "${WORK}/regular.off" --report "${WORK}/regular.json")
file(READ "${WORK}/regular.json" regular)
string(JSON nz GET "${regular}" planes 1 normal 2)
string(JSON turn GET "${regular}" regularization largest_turn_degrees)
if(NOT nz EQUAL 0 OR turn LESS 1.1 OR turn GREATER 1.2)
  message(FATAL_ERROR "--regularize 2: the second plane's normal z ${nz} (expected 0), turned ${turn} degrees")
endif()
run_tool(symmetry symmetrize "${MESH}" -q --plane 0,0,1,0 --plane 1,0,0,0 --iterations 2 --output "${WORK}/given.off"
         --report "${WORK}/given.json")
file(READ "${WORK}/given.json" given)
string(JSON n LENGTH "${given}" planes)
string(JSON nx GET "${given}" planes 1 normal 0)
string(JSON regularization TYPE "${given}" regularization)
if(NOT n EQUAL 2 OR NOT nx EQUAL 1 OR NOT regularization STREQUAL "NULL")
  message(FATAL_ERROR "--plane twice: ${n} planes, the second's normal x ${nx}, regularization ${regularization}")
endif()
