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
