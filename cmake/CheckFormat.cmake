# Fails when a C++ file of the project is not formatted as .clang-format says (clang-format 14).
#   cmake -DROOT=<source dir> -DCLANG_FORMAT=<clang-format> -P cmake/CheckFormat.cmake
cmake_minimum_required(VERSION 3.16)
set(globs)
foreach(dir libmrpt_topoeval apps tests bench examples python)
    list(APPEND globs "${ROOT}/${dir}/*.cpp" "${ROOT}/${dir}/*.h")
endforeach()
file(GLOB_RECURSE files ${globs})
list(FILTER files EXCLUDE REGEX "/tests/data/")
list(LENGTH files n)
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${files}
                WORKING_DIRECTORY "${ROOT}" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "formatting: files differ from .clang-format (fix: clang-format -i FILE):\n${err}")
endif()
message(STATUS "formatting: ${n} files as .clang-format says")
