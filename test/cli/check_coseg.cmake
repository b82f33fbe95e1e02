cmake_minimum_required(VERSION 3.19)
# `shape_analysis coseg` on a set of meshes: per mesh, NAME.seg with one label per input face and
# NAME.ply (binary, one face per input face, an integer 'segment' per face) in the output
# directory (created, nested, when missing); the report gives the segments of every mesh, which
# must be the labels found in its .seg file, and the figures of the correspondences; the result
# is the same with one thread as with two.
#   cmake -DEXE=<tool> -DMESHES="a.off|b.off|c.off" -DFACES="na|nb|nc" -DWORK=<dir>
#         -P check_coseg.cmake
string(REPLACE "|" ";" meshes "${MESHES}")
string(REPLACE "|" ";" faces "${FACES}")
list(LENGTH meshes m)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(common -k 6 --points 300 --seed 2 -q)

foreach(threads 2 1)
  set(dir "${WORK}/out${threads}/nested")
  execute_process(COMMAND "${EXE}" coseg ${meshes} ${common} --threads ${threads}
                          --output-dir "${dir}" --report "${WORK}/report${threads}.json"
                  RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  message(STATUS "exit ${r}\nstdout: ${out}\nstderr: ${err}")
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "coseg failed: ${err}")
  endif()
  file(GLOB leftovers "${dir}/*.tmp*")
  if(leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
  endif()
endforeach()

set(dir "${WORK}/out2/nested")
file(READ "${WORK}/report2.json" report)
foreach(key command seconds segments meshes_of_segment segment_area segment_label oversegments
            aligned_pairs correspondences mean_alignment_rms runs chosen_run run_disagreement)
  string(JSON value ERROR_VARIABLE missing GET "${report}" ${key})
  if(missing)
    message(FATAL_ERROR "the report has no '${key}': ${report}")
  endif()
endforeach()
string(JSON segments GET "${report}" segments)
string(JSON n_reported LENGTH "${report}" meshes)
string(JSON n_meshes_of_segment LENGTH "${report}" meshes_of_segment)
string(JSON n_area LENGTH "${report}" segment_area)
string(JSON pairs GET "${report}" aligned_pairs)
string(JSON correspondences GET "${report}" correspondences)
math(EXPR expected_pairs "${m} * (${m} - 1) / 2")
if(NOT n_reported EQUAL m OR NOT n_meshes_of_segment EQUAL segments OR NOT n_area EQUAL segments)
  message(FATAL_ERROR "${n_reported} meshes, ${n_meshes_of_segment} and ${n_area} entries for "
                      "${segments} segments in the report")
endif()
if(NOT pairs EQUAL expected_pairs OR NOT correspondences GREATER 0)
  message(FATAL_ERROR "${pairs} aligned pairs (expected ${expected_pairs}), ${correspondences} correspondences")
endif()

math(EXPR last "${m} - 1")
foreach(i RANGE ${last})
  list(GET meshes ${i} mesh)
  list(GET faces ${i} n_faces)
  get_filename_component(name "${mesh}" NAME_WE)
  # Labels: one per input face, in [0, segments), the set the report gives for this mesh.
  file(STRINGS "${dir}/${name}.seg" labels)
  list(LENGTH labels n)
  if(NOT n EQUAL n_faces)
    message(FATAL_ERROR "${name}.seg has ${n} lines, expected ${n_faces}")
  endif()
  list(REMOVE_DUPLICATES labels)
  list(SORT labels COMPARE NATURAL)
  string(JSON n_present LENGTH "${report}" meshes ${i} segments)
  set(reported "")
  math(EXPR last_present "${n_present} - 1")
  foreach(k RANGE ${last_present})
    string(JSON s GET "${report}" meshes ${i} segments ${k})
    list(APPEND reported ${s})
  endforeach()
  if(NOT labels STREQUAL reported)
    message(FATAL_ERROR "${name}.seg has the labels '${labels}', the report says '${reported}'")
  endif()
  foreach(s ${labels})
    if(s LESS 0 OR NOT s LESS segments)
      message(FATAL_ERROR "${name}.seg has the label ${s}, not in [0, ${segments})")
    endif()
  endforeach()
  string(JSON reported_faces GET "${report}" meshes ${i} faces)
  if(NOT reported_faces EQUAL n_faces)
    message(FATAL_ERROR "the report gives ${reported_faces} faces for ${name}, expected ${n_faces}")
  endif()
  # The coloured mesh: a binary PLY with every input face and its segment.
  file(READ "${dir}/${name}.ply" header LIMIT 400)
  if(NOT header MATCHES "^ply\nformat binary_little_endian 1.0\n" OR
     NOT header MATCHES "element face ${n_faces}\n" OR NOT header MATCHES "property int segment\n")
    message(FATAL_ERROR "${name}.ply is not the expected PLY: ${header}")
  endif()
  # The same result with one thread.
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${dir}/${name}.seg"
                          "${WORK}/out1/nested/${name}.seg" RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${name}.seg differs between 1 and 2 threads")
  endif()
endforeach()
