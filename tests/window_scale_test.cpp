// The window at fast quality draws the scene at render.window_scale of its pixels per side and
// scales it up (vis/render/render_quality.hpp, docs/view.md "Render quality"): the default scene,
// paused at t = 0, in a 1280x800 virtual screen (xvfb-run) at scale 0.5 and at 1. The summary
// line names the pixels drawn, and the two screenshots right of the panel agree once fine detail
// is averaged away (8 x 8 pixel blocks: measured a mean of 0.84/255 and 0.8 % of the blocks off
// by more than 8/255); a scene drawn into the wrong part of the window, or not scaled up, is off
// by tens.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

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

struct BlockDifference {
  double mean = 0.0;  // mean |difference| of the blocks' averages over the channels, in 1/255
  double over = 0.0;  // share of blocks with a channel's average off by more than 8/255
};

// a and b compared as averages over k x k blocks of the columns from x0 on.
BlockDifference block_difference(const clothlab::Image& a, const clothlab::Image& b, int x0,
                                 int k) {
  BlockDifference d;
  long blocks = 0, over = 0;
  for (int by = 0; by + k <= a.height; by += k) {
    for (int bx = x0; bx + k <= a.width; bx += k) {
      double worst = 0.0;
      for (int ch = 0; ch < 3; ++ch) {
        double sum = 0.0;
        for (int y = by; y < by + k; ++y)
          for (int x = bx; x < bx + k; ++x) sum += double(a.at(x, y)[ch]) - double(b.at(x, y)[ch]);
        const double diff = std::abs(sum) / double(k * k);
        d.mean += diff;
        worst = std::max(worst, diff);
      }
      over += worst > 8.0;
      ++blocks;
    }
  }
  d.mean /= 3.0 * double(blocks);
  d.over = double(over) / double(blocks);
  return d;
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
  const BlockDifference d = block_difference(half.image, all.image, 400, 8);
  std::printf("blocks: mean %.3f over %.4f\n", d.mean, d.over);
  EXPECT_LT(d.mean, 1.5);
  EXPECT_LT(d.over, 0.02);
  // Unaveraged they differ (the weave's threads and the edges are softer at half the pixels):
  // the scaled scene is really drawn at fewer pixels.
  EXPECT_GT(block_difference(half.image, all.image, 400, 1).mean, 1.0);
  fs::remove_all(dir);
}

}  // namespace
