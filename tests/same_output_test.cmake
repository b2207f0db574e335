# Runs REFERENCE and then OTHER (each a ;-list: a command and its arguments) and fails unless
# both succeed and print the same standard output. The bindings' twins of
# examples/article_scenarios.cpp are checked with it: the same scenarios through another
# language must print the C++ numbers to the last digit.
#
#   cmake -DREFERENCE="cmd;args" -DOTHER="cmd;args" [-DWORKING_DIRECTORY=dir] -P same_output_test.cmake
if(NOT REFERENCE OR NOT OTHER)
    message(FATAL_ERROR "same_output_test.cmake: give -DREFERENCE=... and -DOTHER=...")
endif()
if(NOT WORKING_DIRECTORY)
    set(WORKING_DIRECTORY ".")
endif()
execute_process(COMMAND ${REFERENCE} WORKING_DIRECTORY "${WORKING_DIRECTORY}"
    OUTPUT_VARIABLE expected ERROR_VARIABLE expected_error RESULT_VARIABLE expected_status)
if(NOT expected_status EQUAL 0)
    message(FATAL_ERROR "the reference failed (${expected_status}): ${REFERENCE}\n${expected_error}")
endif()
execute_process(COMMAND ${OTHER} WORKING_DIRECTORY "${WORKING_DIRECTORY}"
    OUTPUT_VARIABLE actual ERROR_VARIABLE actual_error RESULT_VARIABLE actual_status)
if(NOT actual_status EQUAL 0)
    message(FATAL_ERROR "the program failed (${actual_status}): ${OTHER}\n${actual_error}")
endif()
if(NOT actual STREQUAL expected)
    message(FATAL_ERROR "the outputs differ.\n--- ${REFERENCE}\n${expected}\n--- ${OTHER}\n${actual}")
endif()
message(STATUS "same output (${OTHER})")
