// The second error channel (as pbrt's CHECK macros): a broken invariant of the program itself,
// not bad input. CLOTHLAB_CHECK(x) and CLOTHLAB_CHECK_EQ(a, b) (NE, LT, LE, GT, GE) print the
// expression, the values it compared and the C++ file and line to stderr, then abort. Bad input
// (a scene, an argument, a file) is a SceneError with its file, line and key instead: a user can
// act on that one; this one is a bug to report.
#pragma once

#include <sstream>
#include <string>

namespace clothlab::detail {

[[noreturn]] void check_failed(const char* file, int line, const char* expression,
                               const std::string& values);

template <class A, class B>
std::string check_values(const A& a, const B& b) {
  std::ostringstream text;
  text << a << " vs " << b;
  return text.str();
}

}  // namespace clothlab::detail

#define CLOTHLAB_CHECK(x)                                                              \
  do {                                                                                 \
    if (!(x)) ::clothlab::detail::check_failed(__FILE__, __LINE__, #x, std::string()); \
  } while (false)

#define CLOTHLAB_CHECK_OP(a, op, b)                                              \
  do {                                                                           \
    const auto& clothlab_check_a = (a);                                          \
    const auto& clothlab_check_b = (b);                                          \
    if (!(clothlab_check_a op clothlab_check_b))                                 \
      ::clothlab::detail::check_failed(                                          \
          __FILE__, __LINE__, #a " " #op " " #b,                                 \
          ::clothlab::detail::check_values(clothlab_check_a, clothlab_check_b)); \
  } while (false)

#define CLOTHLAB_CHECK_EQ(a, b) CLOTHLAB_CHECK_OP(a, ==, b)
#define CLOTHLAB_CHECK_NE(a, b) CLOTHLAB_CHECK_OP(a, !=, b)
#define CLOTHLAB_CHECK_LT(a, b) CLOTHLAB_CHECK_OP(a, <, b)
#define CLOTHLAB_CHECK_LE(a, b) CLOTHLAB_CHECK_OP(a, <=, b)
#define CLOTHLAB_CHECK_GT(a, b) CLOTHLAB_CHECK_OP(a, >, b)
#define CLOTHLAB_CHECK_GE(a, b) CLOTHLAB_CHECK_OP(a, >=, b)
