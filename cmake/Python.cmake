# SPDX-License-Identifier: Apache-2.0
#
# The Python package (python/) tested under ctest against the shared
# library of this build: pytest over python/tests with TRACELIST_LIBRARY
# set, using the first Python 3 that has numpy and pytest (the system's
# python3 on Debian, where python3-numpy and python3-pytest are packages).
# scripts/test.sh also installs the package with pip into a virtual
# environment and runs the same tests against the installed copy.
set(rt_python "")
foreach(candidate ${RT_PYTHON} python3 /usr/bin/python3)
  execute_process(COMMAND ${candidate} -c "import sys, numpy, pytest; print(sys.executable)"
    RESULT_VARIABLE rt_python_rc OUTPUT_VARIABLE rt_python_exe ERROR_QUIET)
  if(rt_python_rc EQUAL 0)
    string(STRIP "${rt_python_exe}" rt_python)
    break()
  endif()
endforeach()
if(NOT rt_python OR RT_SANITIZE)
  message(STATUS "Tracelist: Python with numpy and pytest not found (or sanitizer build) - python tests switched off")
  return()
endif()
message(STATUS "Tracelist: Python tests with ${rt_python}")
add_test(NAME python/pytest
  COMMAND ${rt_python} -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/python/tests
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/python)
set_tests_properties(python/pytest PROPERTIES LABELS python TIMEOUT 300
  ENVIRONMENT "TRACELIST_LIBRARY=$<TARGET_FILE:tracelist>")
# The benchmark script at toy size: Python and C must get identical hits.
if(TARGET trace_rays_file)
  add_test(NAME python/benchmark_smoke
    COMMAND ${rt_python} ${PROJECT_SOURCE_DIR}/python/benchmark.py --rays 20000 --runs 1
            --threads 2 --c-bench $<TARGET_FILE:trace_rays_file>)
  set_tests_properties(python/benchmark_smoke PROPERTIES LABELS python TIMEOUT 300
    ENVIRONMENT "TRACELIST_LIBRARY=$<TARGET_FILE:tracelist>")
endif()
