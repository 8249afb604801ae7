#include "sim/core/check.hpp"

#include <cstdio>
#include <cstdlib>

namespace clothlab::detail {

void check_failed(const char* file, int line, const char* expression, const std::string& values) {
  std::fprintf(stderr, "%s:%d: CLOTHLAB_CHECK(%s) failed%s%s\n", file, line, expression,
               values.empty() ? "" : ": ", values.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace clothlab::detail
