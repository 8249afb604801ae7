// The window at fast quality draws the scene at render.window_scale of its pixels per side and
// scales it up (vis/render/render_quality.hpp, docs/view.md "Render quality"): the default scene,
// paused at t = 0, in a 1280x800 virtual screen (xvfb-run) at scale 0.5 and at 1. The summary
// line names the pixels drawn, and the two screenshots right of the panel agree once fine detail
// is averaged away (8 x 8 pixel blocks: measured a mean of 0.86/255 and 0.8 % of the blocks off
// by more than 8/255); a scene drawn into the wrong part of the window, or not scaled up, is off
// by tens.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "image_compare.hpp"
#include "vis/textures/image.hpp"

namespace {

namespace fs = std::filesystem;

struct WindowShot {
  std::string summary;  // everything the window printed
  clothlab::Image image;
};

// The default scene in the window at `scale`, paused on its first frame, its last frame saved.
WindowShot shoot(const fs::path& dir, const std::string& scale) {
  const fs::path png = dir / ("scale_" + scale + ".png"), log = dir / ("scale_" + scale + ".txt");
  const std::string cmd =
      "env -u WAYLAND_DISPLAY CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=4 CLOTHLAB_VIEW_KEYS=Space "
      "CLOTHLAB_VIEW_NO_AUDIO=1 CLOTHLAB_VIEW_SCREENSHOT='" +
      png.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" + std::string(CLOTHLAB_BINARY) +
      "' view --set render.quality=fast --set render.window_scale=" + scale + " >'" + log.string() +
      "' 2>&1";
  const int status = std::system(cmd.c_str());
  WindowShot shot;
  if (std::FILE* f = std::fopen(log.c_str(), "r")) {
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) shot.summary.append(buffer, n);
    std::fclose(f);
  }
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << shot.summary;
  if (fs::exists(png)) shot.image = clothlab::read_png(png.string());
  return shot;
}

// The columns of `image` from x0 on, averaged over k x k blocks (rounded to 8 bits).
clothlab::Image blocks(const clothlab::Image& image, int x0, int k) {
  clothlab::Image out((image.width - x0) / k, image.height / k);
  for (int by = 0; by < out.height; ++by) {
    for (int bx = 0; bx < out.width; ++bx) {
      for (int ch = 0; ch < 4; ++ch) {
        int sum = 0;
        for (int y = by * k; y < (by + 1) * k; ++y)
          for (int x = x0 + bx * k; x < x0 + (bx + 1) * k; ++x) sum += image.at(x, y)[ch];
        out.at(bx, by)[ch] = std::uint8_t((sum + k * k / 2) / (k * k));
      }
    }
  }
  return out;
}

TEST(WindowScale, HalfTheWindowsPixelsKeepTheLookOfAllOfThem) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "needs xvfb-run (scripts/deps installs it)";
  const fs::path dir =
      fs::temp_directory_path() / ("clothlab_window_scale_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const WindowShot half = shoot(dir, "0.5"), all = shoot(dir, "1");
  // The framebuffer is the screen less the window's title bar: its width is 1280.
  EXPECT_NE(half.summary.find("scene drawn at 640x"), std::string::npos) << half.summary;
  EXPECT_NE(all.summary.find("scene drawn at 1280x"), std::string::npos) << all.summary;
  ASSERT_GT(half.image.width, 0);
  ASSERT_EQ(half.image.width, all.image.width);
  ASSERT_EQ(half.image.height, all.image.height);
  const clothlab::testing::Comparison d =
      clothlab::testing::compare(blocks(half.image, 400, 8), blocks(all.image, 400, 8));
  std::printf("8x8 blocks: mean %.3f/255, %.2f %% off by more than 8/255\n", d.mean_abs,
              100.0 * d.fraction_over);
  EXPECT_LT(d.mean_abs, 1.5);
  EXPECT_LT(d.fraction_over, 0.02);
  // Unaveraged they differ (the weave's threads and the edges are softer at half the pixels):
  // the scaled scene is really drawn at fewer pixels.
  EXPECT_GT(
      clothlab::testing::compare(blocks(half.image, 400, 1), blocks(all.image, 400, 1)).mean_abs,
      1.0);
  fs::remove_all(dir);
}

}  // namespace
