# Checks shared by the consumer projects of tests/consumers/: foresight, added as a subproject,
# must leave the parent's build type alone and bring the library without tests, tools,
# benchmarks, backends or install rules.
#
#   foresight_consumer_remember_build_type()   before adding foresight
#   foresight_consumer_check_subproject()      after adding it (FATAL_ERROR on a problem)

macro(foresight_consumer_remember_build_type)
    set(_consumer_build_type "${CMAKE_BUILD_TYPE}")
    get_property(_consumer_build_type_cached CACHE CMAKE_BUILD_TYPE PROPERTY VALUE)
endmacro()

function(foresight_consumer_check_subproject)
    get_property(_cached_now CACHE CMAKE_BUILD_TYPE PROPERTY VALUE)
    if(NOT "${CMAKE_BUILD_TYPE}" STREQUAL "${_consumer_build_type}"
       OR NOT "${_cached_now}" STREQUAL "${_consumer_build_type_cached}")
        message(FATAL_ERROR "foresight changed the parent's CMAKE_BUILD_TYPE from "
            "'${_consumer_build_type}' (cache '${_consumer_build_type_cached}') to "
            "'${CMAKE_BUILD_TYPE}' (cache '${_cached_now}')")
    endif()
    if(NOT TARGET foresight::foresight)
        message(FATAL_ERROR "foresight::foresight is not defined")
    endif()
    foreach(_target foresight_tests foresight_cli foresight_bench foresight_embree foresight_bullet foresight_c)
        if(TARGET ${_target})
            message(FATAL_ERROR "foresight as a subproject defined ${_target}: tests, tools, "
                "benchmarks and backends must be off by default")
        endif()
    endforeach()
    foreach(_option FORESIGHT_BUILD_TESTS FORESIGHT_BUILD_TOOLS FORESIGHT_BUILD_BENCHMARKS FORESIGHT_BUILD_C_API
             FORESIGHT_INSTALL)
        if(${_option})
            message(FATAL_ERROR "${_option} is ON in a subproject build; it should default to OFF")
        endif()
    endforeach()
    message(STATUS "consumer: foresight added as a subproject; CMAKE_BUILD_TYPE still "
        "'${CMAKE_BUILD_TYPE}', no tests, tools, benchmarks, backends or install rules")
endfunction()
