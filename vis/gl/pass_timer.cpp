#include "vis/gl/pass_timer.hpp"

namespace clothlab::vis {

PassTimer::~PassTimer() {
  if (!pool_.empty()) glDeleteQueries(static_cast<GLsizei>(pool_.size()), pool_.data());
}

void PassTimer::begin(Pass pass) {
  end();
  if (segments_.size() == pool_.size()) {
    GLuint q = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &q);
    pool_.push_back(q);
  }
  glBeginQuery(GL_TIME_ELAPSED, pool_[segments_.size()]);
  segments_.push_back(pass);
  open_ = true;
}

void PassTimer::end() {
  if (!open_) return;
  glEndQuery(GL_TIME_ELAPSED);
  open_ = false;
}

std::array<double, kPassCount> PassTimer::collect() {
  end();
  std::array<double, kPassCount> ms{};
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(pool_[i], GL_QUERY_RESULT, &ns);  // waits for the result
    ms[static_cast<std::size_t>(segments_[i])] += 1e-6 * static_cast<double>(ns);
  }
  segments_.clear();
  return ms;
}

}  // namespace clothlab::vis
