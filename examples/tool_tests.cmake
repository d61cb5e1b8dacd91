# cgal_ext_tool_fails(NAME TOOL ARGS STDERR): a CTest test that runs TOOL
# with ARGS (a ;-list) and passes if it exits with status 2, prints nothing
# on stdout and one line matching the regex STDERR on stderr, as every tool
# does for a bad file or argument (check_tool.cmake checks the streams apart).
function(cgal_ext_tool_fails name tool args stderr)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${tool}> "-DARGS=${args}" -DSTATUS=2 "-DSTDERR=${stderr}"
            -P ${PROJECT_SOURCE_DIR}/examples/check_tool.cmake)
endfunction()
