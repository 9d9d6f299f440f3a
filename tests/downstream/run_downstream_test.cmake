# Run by ctest (test `downstream_find_package`):
#   cmake -DSOURCE_DIR=<project> -DBINARY_DIR=<its build> -DWORK_DIR=<scratch> -P this_file
# Installs the already-built project into WORK_DIR/prefix, then configures, builds and runs the
# downstream project in this folder against that prefix only. Any failing step fails the test.
cmake_minimum_required(VERSION 3.16)

foreach(var SOURCE_DIR BINARY_DIR WORK_DIR)
    if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
        message(FATAL_ERROR "run_downstream_test.cmake: -D${var}=... is required")
    endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
# A fresh prefix every time, so no file left from an earlier install can hide a packaging bug.
# The downstream build folder is kept: `cmake --install` gives installed files the build tree's
# timestamps, so when nothing changed the downstream build is a no-op (CI starts from scratch).
file(REMOVE_RECURSE "${prefix}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs one step; prints its output, and stops the test with it when the step fails.
function(run_step name)
    execute_process(COMMAND ${ARGN}
                    RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out
                    ERROR_VARIABLE out)
    if(NOT rc STREQUAL "0")
        message(FATAL_ERROR "downstream test: ${name} failed (${rc}):\n"
                            "  command: ${ARGN}\n${out}")
    endif()
    message(STATUS "downstream test: ${name}: ok")
    set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("install into ${prefix}"
         "${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${prefix}")
# Public headers speak MRPT and Eigen only (doc/style.md): CGAL and OpenCV stay private.
file(GLOB_RECURSE installed_headers "${prefix}/include/mrpt_topoeval/*")
if(NOT installed_headers)
    message(FATAL_ERROR "downstream test: no headers installed in ${prefix}/include/mrpt_topoeval")
endif()
foreach(h ${installed_headers})
    file(STRINGS "${h}" private_includes REGEX "#[ \t]*include[ \t]*[<\"](CGAL|opencv2?)/")
    if(private_includes)
        message(FATAL_ERROR "downstream test: installed header ${h} includes a private "
                            "dependency: ${private_includes}")
    endif()
endforeach()

run_step("configure"
         "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/tests/downstream" -B "${build}"
         -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
         # Only the installed package may satisfy find_package(mrpt_topoeval): never the
         # build tree through CMake's user package registry.
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
string(FIND "${step_output}" "from ${prefix}/" at)
if(at EQUAL -1)
    message(FATAL_ERROR "downstream test: mrpt_topoeval was not found in ${prefix}:\n"
                        "${step_output}")
endif()
run_step("build" "${CMAKE_COMMAND}" --build "${build}" --parallel 2)
run_step("run" "${build}/downstream")
message(STATUS "downstream test output:\n${step_output}")
run_step("run example 02_score_map" "${build}/02_score_map")
message(STATUS "${step_output}")
