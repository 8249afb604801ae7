#include "apps/view/screenshot.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "gl/gl.hpp"

namespace clothlab::vis {

Image read_default_framebuffer(int width, int height) {
  Image image(width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's row 0 is the bottom; Image's is the top.
  const std::size_t row = 4 * std::size_t(width);
  std::vector<std::uint8_t> swap(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = image.at(0, y);
    std::uint8_t* b = image.at(0, height - 1 - y);
    std::memcpy(swap.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, swap.data(), row);
  }
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
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
