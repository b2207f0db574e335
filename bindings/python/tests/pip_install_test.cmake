# `pip install` of bindings/python into a fresh virtual environment, then the article example
# runs from the installed module. Offline: --no-index (no registry), --no-build-isolation (the
# interpreter's own setuptools, pybind11 and NumPy, seen through --system-site-packages).
#
#   cmake -DPYTHON=python3 -DSOURCE_DIR=bindings/python -DWORK_DIR=dir [-DREFERENCE=article_scenarios]
#         -P pip_install_test.cmake
if(NOT PYTHON OR NOT SOURCE_DIR OR NOT WORK_DIR)
    message(FATAL_ERROR "pip_install_test.cmake: give -DPYTHON=... -DSOURCE_DIR=... -DWORK_DIR=...")
endif()

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "failed (${status}): ${ARGN}\n${output}")
    endif()
    set(run_output "${output}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(venv "${WORK_DIR}/venv")
run("${PYTHON}" -m venv --system-site-packages "${venv}")
set(venv_python "${venv}/bin/python")

# pip builds in the source folder (build/, *.egg-info): install from a copy of the files
# setup.py reads (include/, src/, bindings/python/ in the repository's layout), so that the
# checkout stays clean.
get_filename_component(root "${SOURCE_DIR}/../.." ABSOLUTE)
set(tree "${WORK_DIR}/tree")
file(COPY "${root}/include" "${root}/src" DESTINATION "${tree}")
file(COPY "${SOURCE_DIR}" DESTINATION "${tree}/bindings" PATTERN "build" EXCLUDE PATTERN "*.egg-info" EXCLUDE
    PATTERN "__pycache__" EXCLUDE)
if(NOT DEFINED ENV{NPY_NUM_BUILD_JOBS})
    set(ENV{NPY_NUM_BUILD_JOBS} 2)  # the compile jobs of setup.py (CI has 2 cores)
endif()
# The test checks the packaging, not the speed: -O1 (measured: 62 s of CPU for the whole test,
# 87 s with -O2).
if(NOT DEFINED ENV{FORESIGHT_OPTIMIZE})
    set(ENV{FORESIGHT_OPTIMIZE} -O1)
endif()
set(ENV{PIP_NO_CACHE_DIR} 1)
set(ENV{PIP_DISABLE_PIP_VERSION_CHECK} 1)
run("${venv_python}" -m pip install --no-build-isolation --no-index "${tree}/bindings/python")

# Import from outside the source folder, so that the installed module is the one found.
run("${venv_python}" -c "import foresight, sys; print(foresight.__file__); sys.exit(0 if '${venv}' in foresight.__file__ else 1)")
message(STATUS "installed: ${run_output}")
execute_process(COMMAND "${venv_python}" "${tree}/bindings/python/examples/article_scenarios.py"
    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT status EQUAL 0 OR NOT output MATCHES "^character\n.*grenade jolt: .*car\n")
    message(FATAL_ERROR "the example failed (${status}) from the installed module:\n${output}\n${error}")
endif()
# With the C++ program given, the installed module must print its text exactly, as the built one does.
if(REFERENCE)
    execute_process(COMMAND "${REFERENCE}" OUTPUT_VARIABLE expected RESULT_VARIABLE status)
    if(NOT status EQUAL 0 OR NOT output STREQUAL expected)
        message(FATAL_ERROR "the installed module's output differs from ${REFERENCE}:\n${output}\n---\n${expected}")
    endif()
endif()
message(STATUS "the example ran from the installed module")
file(REMOVE_RECURSE "${venv}" "${tree}")
