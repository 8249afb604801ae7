#include "gl/pass_timer.hpp"

#include "gl/gl.hpp"

namespace clothlab::vis {

void PassTimer::begin(Pass pass) {
  end();
  glFinish();  // what came before is not this pass's work
  open_pass_ = pass;
  started_ = std::chrono::steady_clock::now();
}

void PassTimer::end() {
  if (open_pass_ == Pass::count) return;
  glFinish();
  const std::chrono::duration<double, std::milli> took =
      std::chrono::steady_clock::now() - started_;
  ms_[static_cast<std::size_t>(open_pass_)] += took.count();
  open_pass_ = Pass::count;
}

std::array<double, kPassCount> PassTimer::collect() {
  end();
  const std::array<double, kPassCount> out = ms_;
  ms_ = {};
  return out;
}

}  // namespace clothlab::vis
