# No class, struct, union or function over 120 lines in the project's sources (issue 55;
# docs/testing.md, "Definition lengths"), measured by universal-ctags' spans.
set(_sources sim gpu gl vis apps bench load music python factory tune)
add_test(NAME lengths.sources
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/long_definitions ${_sources}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# The check itself: of a class at the limit and one a line over it, it names only the second.
set(_fixture ${CMAKE_CURRENT_BINARY_DIR}/long_definitions)
add_test(NAME lengths.names_the_one_over_the_limit
  COMMAND sh -c "/usr/bin/python3 '${CMAKE_CURRENT_LIST_DIR}/long_definition_fixture.py' '${_fixture}' && /usr/bin/python3 '${PROJECT_SOURCE_DIR}/scripts/long_definitions' '${_fixture}'")
set_tests_properties(lengths.names_the_one_over_the_limit PROPERTIES
  PASS_REGULAR_EXPRESSION "fixture.cpp:[0-9]+: class OneLineTooLong is 121 lines \\(limit 120\\)"
  FAIL_REGULAR_EXPRESSION "AtTheLimit")
