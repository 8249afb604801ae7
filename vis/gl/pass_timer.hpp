// GPU time per render pass through OpenGL timer queries (GL_TIME_ELAPSED, core since 3.3): for
// benchmarks, which switch it on; a renderer without it issues no queries. A pass may be timed
// in several segments in one frame (the scene before and after the sky); collect() sums them.
// Reading the results waits for the GPU, so a frame's times are read after it has finished.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "vis/gl/gl.hpp"

namespace clothlab::vis {

enum class Pass : std::size_t { shadow, diffusion, scene, sky, overlay, count };
inline constexpr std::size_t kPassCount = static_cast<std::size_t>(Pass::count);

class PassTimer {
 public:
  PassTimer() = default;
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  void begin(Pass pass);  // ends the open segment, if any, and opens one for `pass`
  void end();
  // Milliseconds of GPU time per pass in the frame so far (0 for passes not drawn); starts the
  // next frame.
  std::array<double, kPassCount> collect();

 private:
  std::vector<GLuint> pool_;    // query objects, reused from frame to frame
  std::vector<Pass> segments_;  // the pass of each query used this frame, in order
  bool open_ = false;
};

}  // namespace clothlab::vis
