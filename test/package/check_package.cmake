cmake_minimum_required(VERSION 3.16)
# Installs the project from BUILD_DIR into a temporary prefix, then configures, builds and runs a
# consumer project that uses find_package(CGAL_Shape_analysis) and links CGAL::Shape_analysis.
#   cmake -DBUILD_DIR=<project build> -DWORK=<scratch> -DCONSUMER=<consumer source>
#         [-DLAUNCHER=<ccache>] -P check_package.cmake
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix"
                RESULT_VARIABLE r OUTPUT_QUIET)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
if(NOT EXISTS "${WORK}/prefix/include/CGAL/Consistent_segmentation/hierarchical_segmentation.h")
  message(FATAL_ERROR "headers not installed")
endif()
# The installed headers are the library's algorithms and types only: nothing of the support code
# (generators, reports, metrics) that the tool, the tests and the benchmarks share.
file(GLOB_RECURSE installed RELATIVE "${WORK}/prefix/include" "${WORK}/prefix/include/*")
foreach(f ${installed})
  if(f MATCHES "Shape_analysis_support|Procedural_|Urban_scene|Scanned_objects|Json|Partition_agreement")
    message(FATAL_ERROR "support code installed with the library: include/${f}")
  endif()
endforeach()
set(launcher "")
if(LAUNCHER)
  set(launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S "${CONSUMER}" -B "${WORK}/build"
                        -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release ${launcher}
                RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build"
                RESULT_VARIABLE r OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT r EQUAL 0)
  message(FATAL_ERROR "building the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND "${WORK}/build/consumer" RESULT_VARIABLE r OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT r EQUAL 0)
  message(FATAL_ERROR "the consumer failed")
endif()
