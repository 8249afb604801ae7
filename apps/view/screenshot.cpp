#include "apps/view/screenshot.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "gl/draw_state.hpp"

namespace clothlab::vis {

Image read_default_framebuffer(int width, int height) {
  Image image(width, height);
  image.rgba = read_window_rgba(width, height);
  return image;
}

namespace {

// "<prefix>_<YYYYmmdd_HHMMSS_mmm><suffix>" in local time.
std::string stamped_name(const char* prefix, const char* suffix) {
  using namespace std::chrono;
  const auto now = system_clock::now();
  const std::time_t seconds = system_clock::to_time_t(now);
  const long ms =
      static_cast<long>(duration_cast<milliseconds>(now.time_since_epoch()).count() % 1000);
  std::tm local{};
  localtime_r(&seconds, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", &local);
  char name[96];
  std::snprintf(name, sizeof name, "%s_%s_%03ld%s", prefix, stamp, ms, suffix);
  return name;
}

}  // namespace

std::string screenshot_file_name() {
  return stamped_name("clothlab_screenshot", ".png");
}

std::string record_file_name() {
  return stamped_name("clothlab_record", ".csv");
}

}  // namespace clothlab::vis
