# topoeval_unity_build(target): the target compiled 8 sources at a time when
# TOPOEVAL_UNITY_BUILD is ON (top-level CMakeLists.txt).
function(topoeval_unity_build target)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ${TOPOEVAL_UNITY_BUILD}
                                               UNITY_BUILD_BATCH_SIZE 8)
endfunction()

# One place for the warning flags of every target (KISS-ICP habit).
function(topoeval_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE -Wshadow=local -Wno-stringop-overread)
    else()
        # clang (the fuzz build) knows neither -Wshadow=local nor -Wstringop-overread.
        target_compile_options(${target} PRIVATE -Wshadow-uncaptured-local)
    endif()
endfunction()
