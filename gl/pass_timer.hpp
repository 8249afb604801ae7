// Time per render pass, for benchmarks (which switch it on; a renderer without it adds nothing).
// Each boundary between passes waits for the GL to finish (glFinish) and reads a steady clock:
// Mesa's llvmpipe renders lazily, at the next flush, so GL timer queries there charge one pass
// with another's work, while finishing each pass charges every pass with its own. The price is
// that passes no longer overlap, so the sum is a little above an unmeasured frame.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace clothlab::vis {

enum class Pass : std::size_t { shadow, diffusion, scene, sky, overlay, count };
inline constexpr std::size_t kPassCount = static_cast<std::size_t>(Pass::count);

class PassTimer {
 public:
  // Finishes the open pass (if any) and starts `pass`; a pass may run in several segments in a
  // frame (the scene before and after the sky), which add up.
  void begin(Pass pass);
  void end();
  // Milliseconds per pass in the frame so far (0 for passes not drawn); starts the next frame.
  std::array<double, kPassCount> collect();

 private:
  std::array<double, kPassCount> ms_{};
  Pass open_pass_ = Pass::count;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace clothlab::vis
