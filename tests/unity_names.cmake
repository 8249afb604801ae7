# No two files of one folder (the .cpp files of one compile target) define the same name with
# internal linkage: the unity build compiles them together (docs/testing.md, "Build time").
set(_folders sim vis apps/view apps/clothlab bench/suites python tune gl gpu music load factory tests)
add_test(NAME lint.unity_names
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/unity_names ${_folders}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# The check itself: of two files that both define a helper of one name in an anonymous namespace
# (different signatures, which a batch would overload silently), it names the helper; a class
# member of that name and a public function elsewhere are not reported.
set(_fixture ${CMAKE_CURRENT_BINARY_DIR}/unity_names_fixture)
file(MAKE_DIRECTORY ${_fixture})
file(WRITE ${_fixture}/a.cpp "namespace {\ndouble helper(double x) { return x; }\n}  // namespace\nstruct Box {\n  int member(int i) { return i; }\n};\n")
file(WRITE ${_fixture}/b.cpp "namespace {\nint helper(int x) { return x; }\n}  // namespace\nint member(int i) { return i; }\n")
add_test(NAME lint.unity_names_names_a_shared_helper
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/unity_names ${_fixture})
set_tests_properties(lint.unity_names_names_a_shared_helper PROPERTIES
  PASS_REGULAR_EXPRESSION "'helper' is defined in 2 places: [^\n]*a.cpp:2 [^\n]*b.cpp:2"
  FAIL_REGULAR_EXPRESSION "'member'")
