# One place for the warning flags of every target (KISS-ICP habit).
function(topoeval_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local
                                             -Wno-stringop-overread)
endfunction()
