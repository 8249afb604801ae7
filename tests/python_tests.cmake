# The Python module's tests (pytest, tests/python/), one ctest per file, run by Debian's Python
# with the build tree's package first on its path. Not in the sanitizer build (no module there).
if(CLOTHLAB_PYTHON)
  file(GLOB PYTHON_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/python/test_*.py)
  foreach(test_file ${PYTHON_TESTS})
    get_filename_component(name ${test_file} NAME_WE)
    string(REGEX REPLACE "^test_" "" name ${name})
    add_test(NAME python.${name}
             COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider ${test_file}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties(python.${name} PROPERTIES TIMEOUT 600 ENVIRONMENT
      "PYTHONPATH=${CLOTHLAB_PYTHONPATH};CLOTHLAB_BINARY=$<TARGET_FILE:clothlab>;PYTHONDONTWRITEBYTECODE=1")
    if(name MATCHES "^(sweep|readme|tune)$")  # they time runs or start clusters: alone
      set_tests_properties(python.${name} PROPERTIES RUN_SERIAL TRUE)
    endif()
  endforeach()
endif()
