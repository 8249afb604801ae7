#include <cstdio>
#include <cstdlib>

#include "tests/fuzz/fuzz_targets.hpp"

namespace clothlab::fuzz {
namespace {

// The one context of a fuzzing process (set before the first input, read-only afterwards);
// libFuzzer's entry point has no other way to pass it.
FuzzContext& the_context() {
  static FuzzContext c;
  return c;
}

}  // namespace

void set_context(const FuzzContext& context) {
  the_context() = context;
}
const FuzzContext& context() {
  return the_context();
}

void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace clothlab::fuzz
