cmake_minimum_required(VERSION 3.19)
# `shape_analysis coseg --known`: segmentation transfer. A segmentation of MESH (by `segment`)
# becomes known labels, in two ways: (1) the labels 0, 1, 2 kept and the other faces unknown (-1),
# MESH named by its file name without extension; (2) every third face unknown and the others'
# labels shifted by 10, MESH named by its path, the option before the meshes (it takes one value),
# with a prior segmentation of OTHER named by its file name. Each time every non-negative known
# label must be the face's label in MESH's output, the report must carry the known labels as
# segment labels, and OTHER must be labelled too.
#   cmake -DEXE=<tool> -DMESH=<triangle OFF> -DOTHER=<triangle OFF> -DWORK=<dir>
#         -P check_coseg_transfer.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(name "${MESH}" NAME_WE)
get_filename_component(other "${OTHER}" NAME_WE)

execute_process(COMMAND "${EXE}" segment "${MESH}" -k 5 -q --seg "${WORK}/segments.seg"
                RESULT_VARIABLE r ERROR_VARIABLE err)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "segment failed: ${err}")
endif()
file(STRINGS "${WORK}/segments.seg" segments)
execute_process(COMMAND "${EXE}" segment "${OTHER}" -k 4 -q --seg "${WORK}/prior.seg"
                RESULT_VARIABLE r ERROR_VARIABLE err)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "segment failed: ${err}")
endif()
get_filename_component(other_file "${OTHER}" NAME)

foreach(variant 1 2)
  set(known "")
  set(i 0)
  foreach(s IN LISTS segments)
    math(EXPR third "${i} % 3")
    if(variant EQUAL 1)
      if(s LESS 3)
        list(APPEND known ${s})
      else()
        list(APPEND known -1)
      endif()
    elseif(third EQUAL 2)
      list(APPEND known -1)
    else()
      math(EXPR shifted "${s} + 10")
      list(APPEND known ${shifted})
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
  string(REPLACE ";" "\n" text "${known}")
  file(WRITE "${WORK}/known${variant}.seg" "${text}\n")
  if(variant EQUAL 1)
    set(args "${MESH}" "${OTHER}" --known "${name}=${WORK}/known${variant}.seg")
  else()
    set(args --known "${MESH}=${WORK}/known${variant}.seg" "${MESH}"
             --prior "${other_file}=${WORK}/prior.seg" "${OTHER}")
  endif()

  set(dir "${WORK}/out${variant}")
  execute_process(COMMAND "${EXE}" coseg ${args} -k 6 --points 300 -q
                          --output-dir "${dir}" --report "${WORK}/report${variant}.json"
                  RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  message(STATUS "exit ${r}\nstdout: ${out}\nstderr: ${err}")
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "coseg --known failed: ${err}")
  endif()

  file(STRINGS "${dir}/${name}.seg" result)
  list(LENGTH result n_result)
  list(LENGTH known n_known)
  if(NOT n_result EQUAL n_known)
    message(FATAL_ERROR "${name}.seg has ${n_result} lines, expected ${n_known}")
  endif()
  set(face 0)
  set(kept 0)
  foreach(k got IN ZIP_LISTS known result)
    if(k GREATER_EQUAL 0)
      if(NOT got EQUAL k)
        message(FATAL_ERROR "variant ${variant}: face ${face} of ${name} has the known label ${k} but got ${got}")
      endif()
      math(EXPR kept "${kept} + 1")
    endif()
    math(EXPR face "${face} + 1")
  endforeach()
  if(kept LESS 100)
    message(FATAL_ERROR "variant ${variant}: only ${kept} known faces: the test is too weak")
  endif()

  # The known labels are segment labels of the report, with the same id.
  file(READ "${WORK}/report${variant}.json" report)
  set(known_labels ${known})
  list(REMOVE_DUPLICATES known_labels)
  list(REMOVE_ITEM known_labels -1)
  foreach(l ${known_labels})
    string(JSON label GET "${report}" segment_label ${l})
    if(NOT label EQUAL l)
      message(FATAL_ERROR "variant ${variant}: segment ${l} has the label ${label} in the report")
    endif()
  endforeach()
  string(JSON known_file GET "${report}" meshes 0 known)
  string(JSON prior_file GET "${report}" meshes 1 prior)
  if(NOT known_file STREQUAL "${WORK}/known${variant}.seg" OR
     (variant EQUAL 2 AND NOT prior_file STREQUAL "${WORK}/prior.seg"))
    message(FATAL_ERROR "the report names '${known_file}' as known labels, '${prior_file}' as prior")
  endif()

  # The other mesh is labelled too, one label per face.
  file(STRINGS "${dir}/${other}.seg" other_labels)
  list(LENGTH other_labels n_other)
  string(JSON other_faces GET "${report}" meshes 1 faces)
  if(NOT n_other EQUAL other_faces OR n_other EQUAL 0)
    message(FATAL_ERROR "${other}.seg has ${n_other} lines for ${other_faces} faces")
  endif()
endforeach()
