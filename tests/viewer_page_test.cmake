# ctest's viewer.demo_page: writes the demo's viewer page with the CLI, then checks it in Debian's
# chromium with the viewer's browser test. Variables: CLI, NODE, TEST_SCRIPT, PAGE, SCREENSHOT.
execute_process(COMMAND ${CLI} demo --html ${PAGE}
    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "foresight demo --html failed (${status}):\n${output}\n${errors}")
endif()
execute_process(COMMAND ${NODE} ${TEST_SCRIPT} ${PAGE} ${SCREENSHOT}
    RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "the viewer's browser test failed on ${PAGE} (${status})")
endif()
