// The procedural textures: deterministic per seed, the requested size, seamless when tiled,
// and showing the structure they are meant to show (a twill weave with a fixed thread period;
// a checker of stone tiles with grout). Plus PNG round trips and failures.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "vis/textures/fabric_texture.hpp"
#include "vis/textures/floor_texture.hpp"
#include "vis/textures/image.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;

double luminance(const Image& im, int x, int y) {
  const std::uint8_t* p = im.at(x, y);
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];  // Rec. 709 weights
}

// Mean over rows of the summed absolute RGB difference between columns a and b.
double column_difference(const Image& im, int a, int b) {
  double sum = 0.0;
  for (int y = 0; y < im.height; ++y)
    for (int c = 0; c < 3; ++c) sum += std::abs(int(im.at(a, y)[c]) - int(im.at(b, y)[c]));
  return sum / im.height;
}

double row_difference(const Image& im, int a, int b) {
  double sum = 0.0;
  for (int x = 0; x < im.width; ++x)
    for (int c = 0; c < 3; ++c) sum += std::abs(int(im.at(x, a)[c]) - int(im.at(x, b)[c]));
  return sum / im.width;
}

struct SeamReport {
  double seam;    // last column (row) against the first
  double median;  // of adjacent interior column (row) pairs
  double max;
};

template <class Diff>
SeamReport seam_report(int n, Diff diff) {
  std::vector<double> interior;
  for (int k = 0; k + 1 < n; ++k) interior.push_back(diff(k, k + 1));
  std::sort(interior.begin(), interior.end());
  return {diff(n - 1, 0), interior[interior.size() / 2], interior.back()};
}

// A seam is invisible when crossing it changes the image no more than a typical step inside it.
void expect_seamless(const Image& im) {
  const SeamReport cols =
      seam_report(im.width, [&](int a, int b) { return column_difference(im, a, b); });
  const SeamReport rows =
      seam_report(im.height, [&](int a, int b) { return row_difference(im, a, b); });
  EXPECT_LE(cols.seam, std::max(cols.median, 1.0)) << "vertical seam; max " << cols.max;
  EXPECT_LE(rows.seam, std::max(rows.median, 1.0)) << "horizontal seam; max " << rows.max;
}

// Circular autocorrelation (Pearson) of a profile at a lag.
double autocorrelation(const std::vector<double>& f, int lag) {
  const int n = static_cast<int>(f.size());
  double mean = 0.0;
  for (double v : f) mean += v;
  mean /= n;
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    num += (f[i] - mean) * (f[(i + lag) % n] - mean);
    den += (f[i] - mean) * (f[i] - mean);
  }
  return num / den;
}

// Pearson correlation of the luminance with itself shifted by (dx, dy), wrapping around.
double shifted_correlation(const Image& im, int dx, int dy) {
  std::vector<double> a, b;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      a.push_back(luminance(im, x, y));
      b.push_back(luminance(im, (x + dx + im.width) % im.width, (y + dy + im.height) % im.height));
    }
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= a.size();
  mb /= b.size();
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

std::array<double, 3> mean_colour(const Image& im) {
  std::array<double, 3> m{};
  for (std::size_t i = 0; i < im.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) m[c] += im.rgba[i + c];
  for (double& v : m) v /= double(im.width) * im.height;
  return m;
}

std::size_t differing_pixels(const Image& a, const Image& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4)
    if (!std::equal(&a.rgba[i], &a.rgba[i] + 4, &b.rgba[i])) ++n;
  return n;
}

// --- determinism and size ---------------------------------------------------------------

TEST(Textures, SameSeedGivesIdenticalBytes) {
  EXPECT_EQ(make_fabric_texture(128, 7).rgba, make_fabric_texture(128, 7).rgba);
  EXPECT_EQ(make_floor_texture(128, 7).rgba, make_floor_texture(128, 7).rgba);
}

TEST(Textures, DifferentSeedsGiveVisiblyDifferentImages) {
  const Image f1 = make_fabric_texture(128, 1), f2 = make_fabric_texture(128, 2);
  const Image g1 = make_floor_texture(128, 1), g2 = make_floor_texture(128, 2);
  // Per-thread and per-tile variations touch most pixels, not a handful.
  EXPECT_GT(differing_pixels(f1, f2), f1.rgba.size() / 4 / 2);
  EXPECT_GT(differing_pixels(g1, g2), g1.rgba.size() / 4 / 2);
}

TEST(Textures, SizeIsHonouredAndOpaque) {
  for (int size : {1, 16, 32, 64, 128, 256, 512}) {
    for (const Image& im : {make_fabric_texture(size), make_floor_texture(size)}) {
      EXPECT_EQ(im.width, size);
      EXPECT_EQ(im.height, size);
      ASSERT_EQ(im.rgba.size(), std::size_t(size) * size * 4);
      for (std::size_t i = 3; i < im.rgba.size(); i += 4) ASSERT_EQ(im.rgba[i], 255);
    }
  }
}

TEST(Textures, NonPositiveSizeThrows) {
  EXPECT_THROW(make_fabric_texture(0), std::invalid_argument);
  EXPECT_THROW(make_floor_texture(-4), std::invalid_argument);
}

// --- seamless tiling --------------------------------------------------------------------

TEST(Textures, SeamMeasureDetectsASeam) {
  // A horizontal ramp wraps from white to black: the measure must flag it, or the tests below
  // prove nothing.
  Image ramp(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) ramp.set_rgb(x, y, x / 63.0f, x / 63.0f, x / 63.0f);
  const SeamReport r = seam_report(64, [&](int a, int b) { return column_difference(ramp, a, b); });
  EXPECT_GT(r.seam, 10.0 * r.median);
}

TEST(Textures, SeamMeasureDetectsAFabricCutMidThread) {
  // The fabric cut after 15.5 threads: the measure must see the broken thread at the seam.
  const Image full = make_fabric_texture(256, 3);
  Image cut(248, 248);
  for (int y = 0; y < 248; ++y)
    for (int x = 0; x < 248; ++x) std::copy(full.at(x, y), full.at(x, y) + 4, cut.at(x, y));
  const SeamReport r = seam_report(248, [&](int a, int b) { return column_difference(cut, a, b); });
  EXPECT_GT(r.seam, 2.0 * r.median);
}

TEST(Textures, FabricTilesSeamlessly) {
  for (int size : {64, 128, 256}) {
    SCOPED_TRACE(size);
    expect_seamless(make_fabric_texture(size, 3));
  }
}

TEST(Textures, FloorTilesSeamlessly) {
  for (int size : {64, 128, 256}) {
    SCOPED_TRACE(size);
    expect_seamless(make_floor_texture(size, 3));
  }
}

// --- structure --------------------------------------------------------------------------

TEST(Textures, FabricHasThreadPeriodInBothDirections) {
  const int size = 256;
  const Image im = make_fabric_texture(size, 5);
  const int period = size / fabric_thread_count(size);
  ASSERT_EQ(period, 16);
  std::vector<double> column_means(size, 0.0), row_means(size, 0.0);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      column_means[x] += luminance(im, x, y) / size;
      row_means[y] += luminance(im, x, y) / size;
    }
  for (const auto* profile : {&column_means, &row_means}) {
    // The strongest repeat (ignoring the first few lags, which are smooth) is one thread.
    int best = 2;
    for (int lag = 2; lag <= period * 3 / 2; ++lag)
      if (autocorrelation(*profile, lag) > autocorrelation(*profile, best)) best = lag;
    EXPECT_EQ(best, period);
    EXPECT_GT(autocorrelation(*profile, period), 0.8);
    EXPECT_LT(autocorrelation(*profile, period / 2), 0.0);  // thread centre against gap
  }
}

TEST(Textures, FabricIsATwill) {
  // In a 2/2 twill the floats step one thread per row: moving one thread right and one up
  // lands on the same weave state, one right and one down on the opposite one.
  const Image im = make_fabric_texture(256, 5);
  const int p = 256 / fabric_thread_count(256);
  EXPECT_GT(shifted_correlation(im, p, -p), 0.8);
  EXPECT_LT(shifted_correlation(im, p, p), 0.4);
}

TEST(Textures, FloorIsACheckerOfTilesWithGrout) {
  const int size = 256, tile = size / kFloorTiles;
  const Image im = make_floor_texture(size, 9);
  double darkest_light = 255.0, lightest_dark = 0.0;
  for (int ty = 0; ty < kFloorTiles; ++ty)
    for (int tx = 0; tx < kFloorTiles; ++tx) {
      const double centre = luminance(im, tx * tile + tile / 2, ty * tile + tile / 2);
      if ((tx + ty) % 2 == 0)
        darkest_light = std::min(darkest_light, centre);
      else
        lightest_dark = std::max(lightest_dark, centre);
      // Grout lines (the tile's first column and row) are darker than any stone.
      EXPECT_LT(luminance(im, tx * tile, ty * tile + tile / 2), 90.0);
      EXPECT_LT(luminance(im, tx * tile + tile / 2, ty * tile), 90.0);
    }
  EXPECT_GT(darkest_light - lightest_dark, 40.0);
  EXPECT_GT(lightest_dark, 90.0);
}

TEST(Textures, FabricAndFloorHaveClearlyDifferentColours) {
  const auto fabric = mean_colour(make_fabric_texture());
  const auto floor = mean_colour(make_floor_texture());
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c) d2 += (fabric[c] - floor[c]) * (fabric[c] - floor[c]);
  EXPECT_GT(std::sqrt(d2), 80.0);
  EXPECT_GT(fabric[0], 2.0 * fabric[1]);           // the cloth is red
  EXPECT_LT(std::abs(floor[0] - floor[2]), 10.0);  // the floor is grey
}

// --- PNG input and output ---------------------------------------------------------------

class PngTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("clothlab_textures_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PngTest, RoundTripsExactBytes) {
  Image im = make_fabric_texture(64, 4);
  im.at(3, 5)[3] = 17;  // alpha survives too
  const std::string path = (dir_ / "fabric.png").string();
  write_png(im, path);
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const Image back = read_png(path);
  EXPECT_EQ(back.width, im.width);
  EXPECT_EQ(back.height, im.height);
  EXPECT_EQ(back.rgba, im.rgba);
}

TEST_F(PngTest, RoundTripsNonSquareImage) {
  Image im(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) im.set_rgb(x, y, x / 4.0f, y / 2.0f, 0.5f);
  const std::string path = (dir_ / "small.png").string();
  write_png(im, path);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, im.rgba);
}

TEST_F(PngTest, OverwritesAnExistingFile) {
  const std::string path = (dir_ / "floor.png").string();
  write_png(make_floor_texture(32, 1), path);
  const Image second = make_floor_texture(32, 2);
  write_png(second, path);
  EXPECT_EQ(read_png(path).rgba, second.rgba);
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(PngTest, UnwritablePathThrowsNamingItAndLeavesNoFile) {
  // A missing directory is unwritable even for root, unlike a permission bit.
  const std::string path = (dir_ / "missing" / "out.png").string();
  try {
    write_png(make_fabric_texture(16), path);
    FAIL() << "write_png did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(PngTest, InvalidImageThrows) {
  Image im;
  im.width = 4;
  im.height = 4;  // but no pixels
  const std::string path = (dir_ / "bad.png").string();
  EXPECT_THROW(write_png(im, path), std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(PngTest, ReadingAMissingFileThrowsNamingIt) {
  const std::string path = (dir_ / "absent.png").string();
  try {
    read_png(path);
    FAIL() << "read_png did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST_F(PngTest, ReadingANonImageThrows) {
  const std::string path = (dir_ / "text.png").string();
  std::ofstream(path) << "not a png at all";
  EXPECT_THROW(read_png(path), std::runtime_error);
}

}  // namespace
}  // namespace clothlab
