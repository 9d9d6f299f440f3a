# topoeval_unity_build(target): the target compiled 8 sources per translation unit when
# TOPOEVAL_UNITY_BUILD is ON (top-level CMakeLists.txt; doc/building.md, "Unity build").
function(topoeval_unity_build target)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ${TOPOEVAL_UNITY_BUILD}
                                               UNITY_BUILD_BATCH_SIZE 8)
endfunction()
