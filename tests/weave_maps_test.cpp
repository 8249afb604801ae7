// The procedural weave maps (height, normal map, metallic-thread mask, thread direction) and the
// grid cloth's tangent frame: seamless tiling, the normal-map byte encoding and its sign
// convention, the mask's fraction and placement, alignment with the albedo, and the tangent
// frame's direction, orthogonality and handedness on flat, mirrored, deformed and curved grids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "vis/textures/cloth_tangents.hpp"
#include "vis/textures/fabric_texture.hpp"
#include "vis/textures/image.hpp"
#include "vis/textures/weave_maps.hpp"

namespace clothlab {
namespace {

// ---------------------------------------------------------------------------------------------
// Helpers

// Mean absolute difference (over all channels given) between columns a and b, or rows a and b.
template <class Get>
double line_difference(int size, int a, int b, bool columns, Get get) {
  double sum = 0.0;
  for (int k = 0; k < size; ++k) sum += columns ? get(a, k, b, k) : get(k, a, k, b);
  return sum / size;
}

struct Seam {
  double seam, max_interior;
};

// The wrap-around step (last column/row against the first) and the largest step between two
// adjacent interior columns/rows.
template <class Get>
Seam seam(int size, bool columns, Get get) {
  double interior = 0.0;
  for (int k = 0; k + 1 < size; ++k)
    interior = std::max(interior, line_difference(size, k, k + 1, columns, get));
  return {line_difference(size, size - 1, 0, columns, get), interior};
}

double image_diff(const Image& im, int x0, int y0, int x1, int y1) {
  double d = 0.0;
  for (int c = 0; c < 4; ++c) d += std::abs(int(im.at(x0, y0)[c]) - int(im.at(x1, y1)[c]));
  return d;
}

// The weave's period in texels (4 threads, the twill repeat), when it is a whole number.
int twill_period(int size) {
  const int n = fabric_thread_count(size);
  return (4 * size) % n == 0 ? 4 * size / n : 0;
}

float height_at(const std::vector<float>& h, int size, int x, int y) {
  x = (x % size + size) % size;
  y = (y % size + size) % size;
  return h[std::size_t(x) + std::size_t(y) * std::size_t(size)];
}

// ---------------------------------------------------------------------------------------------
// Height

TEST(WeaveHeight, SizeRangeAndErrors) {
  for (int size : {1, 7, 64, 100, 256}) {
    const std::vector<float> h = make_weave_height(size);
    ASSERT_EQ(h.size(), std::size_t(size) * size);
    for (float v : h) {
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
    }
  }
  const std::vector<float> h = make_weave_height(256);
  // The relief spans most of 0..1: gaps at 0, thread crowns near 1.
  EXPECT_EQ(*std::min_element(h.begin(), h.end()), 0.0f);
  EXPECT_GT(*std::max_element(h.begin(), h.end()), 0.95f);
  EXPECT_THROW(make_weave_height(0), std::invalid_argument);
  EXPECT_THROW(make_weave_normal_map(0, 1.0f), std::invalid_argument);
  EXPECT_THROW(make_weave_normal_map(64, -1.0f), std::invalid_argument);
  EXPECT_THROW(make_weave_normal_map(64, NAN), std::invalid_argument);
  EXPECT_THROW(make_flat_normal_map(0), std::invalid_argument);
  EXPECT_THROW(make_thread_direction(-3), std::invalid_argument);
  EXPECT_THROW(make_thread_mask(0, 0.1f, 1), std::invalid_argument);
}

// Sizes whose twill repeat is a whole number of texels: every map is exactly periodic with
// that repeat, across the tile edges too (x + P taken modulo the size), so the wrap-around
// step equals an interior step at the same phase.
TEST(WeaveMaps, PeriodicAcrossTheTileEdges) {
  for (int size : {64, 96, 256}) {
    const int p = twill_period(size);
    ASSERT_GT(p, 0);
    ASSERT_LT(p, size);
    const std::vector<float> h = make_weave_height(size);
    const Image normal = make_weave_normal_map(size, 0.5f);
    const Image dir = make_thread_direction(size);
    int height_mismatch = 0, normal_mismatch = 0, dir_mismatch = 0;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        for (auto [dx, dy] : {std::pair{p, 0}, std::pair{0, p}}) {
          const int x1 = (x + dx) % size, y1 = (y + dy) % size;
          height_mismatch +=
              std::abs(height_at(h, size, x, y) - height_at(h, size, x1, y1)) > 1e-5f;
          normal_mismatch += image_diff(normal, x, y, x1, y1) > 1.0;  // float rounding: 1 LSB
          dir_mismatch += image_diff(dir, x, y, x1, y1) != 0.0;
        }
      }
    }
    EXPECT_EQ(height_mismatch, 0) << "size " << size;
    EXPECT_EQ(normal_mismatch, 0) << "size " << size;
    EXPECT_EQ(dir_mismatch, 0) << "size " << size;
  }
}

// Any size (100: 6.25 texels per thread): crossing the tile edge changes each map no more than
// the largest step between adjacent interior columns (rows) does.
TEST(WeaveMaps, WrapStepIsLikeAnInteriorStep) {
  for (int size : {100, 256}) {
    const std::vector<float> h = make_weave_height(size);
    const Image normal = make_weave_normal_map(size, 0.5f);
    const Image dir = make_thread_direction(size);
    const Image mask = make_thread_mask(size, 0.1f, 3);
    const auto hget = [&](int x0, int y0, int x1, int y1) {
      return double(std::abs(height_at(h, size, x0, y0) - height_at(h, size, x1, y1)));
    };
    for (bool columns : {true, false}) {
      const Seam hs = seam(size, columns, hget);
      EXPECT_LE(hs.seam, hs.max_interior) << "height, size " << size << " columns " << columns;
      for (const Image* im : {&normal, &dir, &mask}) {
        const Seam s = seam(size, columns, [&](int x0, int y0, int x1, int y1) {
          return image_diff(*im, x0, y0, x1, y1);
        });
        EXPECT_LE(s.seam, s.max_interior) << "size " << size << " columns " << columns;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Normal map

TEST(NormalMap, FlatMapIsExactly128_128_255AndDecodesToZ) {
  const Image flat = make_flat_normal_map(16);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const std::uint8_t* p = flat.at(x, y);
      ASSERT_EQ(p[0], 128);
      ASSERT_EQ(p[1], 128);
      ASSERT_EQ(p[2], 255);
      ASSERT_EQ(p[3], 255);
      const glm::vec3 n = decode_normal(p);
      EXPECT_EQ(n.x, 0.0f);
      EXPECT_EQ(n.y, 0.0f);
      EXPECT_EQ(n.z, 1.0f);
    }
  }
  // Strength 0 flattens the weave to the same bytes.
  const Image zero = make_weave_normal_map(64, 0.0f);
  const Image flat64 = make_flat_normal_map(64);
  EXPECT_EQ(zero.rgba, flat64.rgba);
  // The naive 127.5 rule would not give 0 for 128.
  const std::uint8_t mid[3] = {128, 128, 128};
  EXPECT_EQ(decode_normal(mid), glm::vec3(0.0f));
}

TEST(NormalMap, EncodeDecodeRoundTrip) {
  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  for (int k = 0; k < 10000; ++k) {
    glm::vec3 n(g(rng), g(rng), std::abs(g(rng)));
    if (glm::length(n) < 1e-3f) continue;
    n = glm::normalize(n);
    std::uint8_t rgb[3];
    encode_normal(n, rgb);
    const glm::vec3 d = decode_normal(rgb);
    for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(d[c] - n[c]), 0.5f / 127.0f + 1e-6f);
  }
}

TEST(NormalMap, DecodedNormalsAreUnitWithinOneStep) {
  for (float strength : {0.25f, 0.5f, 2.0f}) {
    const Image map = make_weave_normal_map(256, strength);
    int tilted = 0;
    for (int y = 0; y < 256; ++y) {
      for (int x = 0; x < 256; ++x) {
        const glm::vec3 n = decode_normal(map.at(x, y));
        ASSERT_NEAR(glm::length(n), 1.0f, 1.0f / 127.0f) << x << "," << y;
        ASSERT_GE(n.z, 0.0f);
        ASSERT_EQ(map.at(x, y)[3], 255);
        tilted += n.z < 0.99f;
      }
    }
    EXPECT_GT(tilted, 256 * 256 / 4) << "the weave should tilt many normals";
  }
}

// Where the height rises toward +u (+x) the normal tilts toward -u, where it rises toward +v
// (+y, down the rows) toward -v; the tilt matches -strength * slope per thread spacing.
TEST(NormalMap, SignConventionAndSlope) {
  const int size = 256;
  const float strength = 0.5f;
  const std::vector<float> h = make_weave_height(size);
  const Image map = make_weave_normal_map(size, strength);
  const float per_thread = float(size) / float(fabric_thread_count(size));
  int rising_u = 0, rising_v = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float su = 0.5f * (height_at(h, size, x + 1, y) - height_at(h, size, x - 1, y));
      const float sv = 0.5f * (height_at(h, size, x, y + 1) - height_at(h, size, x, y - 1));
      const glm::vec3 n = decode_normal(map.at(x, y));
      const float gu = su * per_thread * strength, gv = sv * per_thread * strength;
      if (gu > 0.2f) {
        ++rising_u;
        EXPECT_LT(n.x, 0.0f) << x << "," << y;
      }
      if (gv > 0.2f) {
        ++rising_v;
        EXPECT_LT(n.y, 0.0f) << x << "," << y;
      }
      // n = normalize(-gu, -gv, 1): the slopes come back as -n.x / n.z, -n.y / n.z.
      if (n.z > 0.3f) {
        EXPECT_NEAR(-n.x / n.z, gu, 0.02f + 0.03f * std::abs(gu)) << x << "," << y;
        EXPECT_NEAR(-n.y / n.z, gv, 0.02f + 0.03f * std::abs(gv)) << x << "," << y;
      }
    }
  }
  EXPECT_GT(rising_u, 1000);
  EXPECT_GT(rising_v, 1000);
}

// ---------------------------------------------------------------------------------------------
// Thread mask and direction

TEST(ThreadDirection, ChannelsAndCoverage) {
  const Image dir = make_thread_direction(256);
  long warp = 0, weft = 0, gap = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const std::uint8_t* p = dir.at(x, y);
      ASSERT_TRUE(p[0] == 0 || p[0] == 255);
      ASSERT_TRUE(p[1] == 0 || p[1] == 255);
      ASSERT_EQ(p[2], 0);
      ASSERT_EQ(p[3], 255);
      if (p[1] == 0) {
        ASSERT_EQ(p[0], 0);
        ++gap;
      } else {
        (p[0] == 255 ? weft : warp) += 1;
      }
    }
  }
  // A balanced 2/2 twill: warp and weft show about equally (the warp wins ties), small gaps.
  const double total = 256.0 * 256.0;
  EXPECT_NEAR(warp / total, weft / total, 0.15);
  EXPECT_GT(gap, 0);
  EXPECT_LT(gap / total, 0.1);
  EXPECT_NEAR(max_metal_fraction(256), weft / total, 1e-6);
}

struct MaskStats {
  long metal = 0;
  bool binary = true, only_weft = true, whole_threads = true;
  std::vector<int> metal_threads;
};

MaskStats mask_stats(int size, const Image& mask, const Image& dir) {
  MaskStats s;
  const int n = fabric_thread_count(size);
  std::vector<int> metal_in_band(n, 0), weft_in_band(n, 0);
  for (int y = 0; y < size; ++y) {
    const int band = int((float(y) + 0.5f) * (float(n) / float(size)));
    for (int x = 0; x < size; ++x) {
      const std::uint8_t* p = mask.at(x, y);
      if (!((p[0] == 0 || p[0] == 255) && p[1] == p[0] && p[2] == p[0] && p[3] == 255))
        s.binary = false;
      const bool weft_top = dir.at(x, y)[0] == 255 && dir.at(x, y)[1] == 255;
      weft_in_band[band] += weft_top;
      if (p[0] == 255) {
        ++s.metal;
        ++metal_in_band[band];
        if (!weft_top) s.only_weft = false;
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    if (metal_in_band[j] != 0 && metal_in_band[j] != weft_in_band[j]) s.whole_threads = false;
    if (metal_in_band[j] != 0) s.metal_threads.push_back(j);
  }
  return s;
}

TEST(ThreadMask, BinaryFractionAndPlacement) {
  for (int size : {100, 256}) {
    const Image dir = make_thread_direction(size);
    const double max_fraction = max_metal_fraction(size);
    const double share = max_fraction / fabric_thread_count(size);  // one weft thread's share
    for (float asked : {0.0f, 0.03f, 0.1f, 0.2f, float(max_fraction), 1.0f}) {
      for (std::uint32_t seed : {1u, 2u, 77u}) {
        const Image mask = make_thread_mask(size, asked, seed);
        const MaskStats s = mask_stats(size, mask, dir);
        EXPECT_TRUE(s.binary);
        EXPECT_TRUE(s.only_weft) << "metal where the weft is not on top";
        EXPECT_TRUE(s.whole_threads) << "a metallic thread must be metallic wherever it shows";
        const double fraction = double(s.metal) / (double(size) * size);
        const double expected = std::min<double>(asked, max_fraction);
        EXPECT_NEAR(fraction, expected, 0.6 * share + 1e-3)
            << "size " << size << " asked " << asked;
      }
    }
  }
  EXPECT_THROW(make_thread_mask(64, -0.1f, 1), std::invalid_argument);
  EXPECT_THROW(make_thread_mask(64, 1.5f, 1), std::invalid_argument);
  EXPECT_THROW(make_thread_mask(64, NAN, 1), std::invalid_argument);
}

// The metallic threads are neighbours, a band whose floats climb the twill's diagonal (spread
// every 4th thread, the twill's period, their floats lined up in a grid of dashes).
TEST(ThreadMask, SeedMovesTheBandOfNeighbouringThreads) {
  const int size = 256, n = fabric_thread_count(size);
  const Image dir = make_thread_direction(size);
  const double share = max_metal_fraction(size) / n;
  std::map<std::vector<int>, int> selections;
  for (std::uint32_t seed = 1; seed <= 16; ++seed) {
    const MaskStats s = mask_stats(size, make_thread_mask(size, float(4 * share), seed), dir);
    ASSERT_EQ(s.metal_threads.size(), 4u);
    // Four neighbours of 16: cyclic gaps 1, 1, 1 and 13.
    std::vector<int> gaps;
    for (std::size_t k = 0; k < 4; ++k)
      gaps.push_back((s.metal_threads[(k + 1) % 4] - s.metal_threads[k] + n) % n);
    std::sort(gaps.begin(), gaps.end());
    EXPECT_EQ(gaps, (std::vector<int>{1, 1, 1, n - 3})) << "seed " << seed;
    ++selections[s.metal_threads];
  }
  EXPECT_GE(selections.size(), 3u) << "the seed should change which threads are metallic";
  // Same seed, same bytes.
  EXPECT_EQ(make_thread_mask(size, 0.1f, 9).rgba, make_thread_mask(size, 0.1f, 9).rgba);
}

// The maps sample the same weave as the albedo: the albedo's gap colour (one colour) shows
// exactly where the direction map reports a gap, and the thread colours agree with the
// direction map on which thread is on top (warp dye: blue/green ~1.1, weft dye ~1.6).
TEST(WeaveMaps, LineUpWithTheAlbedo) {
  const int size = 256;
  const Image albedo = make_fabric_texture(size, 1);
  const Image dir = make_thread_direction(size);
  std::map<std::uint32_t, long> gap_colours;
  const auto key = [](const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (dir.at(x, y)[1] == 0) ++gap_colours[key(albedo.at(x, y))];
  ASSERT_EQ(gap_colours.size(), 1u) << "gap texels should all have the albedo's gap colour";
  const std::uint32_t gap_colour = gap_colours.begin()->first;

  long covered = 0, covered_as_gap = 0, bright = 0, agree = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::uint8_t* a = albedo.at(x, y);
      const std::uint8_t* d = dir.at(x, y);
      if (d[1] == 0) continue;
      ++covered;
      covered_as_gap += key(a) == gap_colour;
      if (a[1] < 20) continue;  // too dark to tell the dyes apart after rounding
      ++bright;
      const bool albedo_weft = double(a[2]) / a[1] > 1.32;
      agree += albedo_weft == (d[0] == 255);
    }
  }
  EXPECT_LT(double(covered_as_gap) / covered, 0.01);
  ASSERT_GT(bright, covered / 10);
  EXPECT_GT(double(agree) / bright, 0.98) << agree << " of " << bright;
}

// ---------------------------------------------------------------------------------------------
// Tangents

struct Grid {
  int nu, nv;
  std::vector<float> pos, normal, tangent;
  Grid(int u, int v) : nu(u), nv(v), pos(3 * u * v), normal(3 * u * v), tangent(4 * u * v, -7.0f) {}
  glm::vec3 p(int i, int j) const {
    const float* q = &pos[3 * (i + j * nu)];
    return {q[0], q[1], q[2]};
  }
  void set_p(int i, int j, glm::vec3 v) {
    float* q = &pos[3 * (i + j * nu)];
    q[0] = v.x, q[1] = v.y, q[2] = v.z;
  }
  glm::vec3 n(int i, int j) const {
    const float* q = &normal[3 * (i + j * nu)];
    return {q[0], q[1], q[2]};
  }
  void set_n(int i, int j, glm::vec3 v) {
    float* q = &normal[3 * (i + j * nu)];
    q[0] = v.x, q[1] = v.y, q[2] = v.z;
  }
  glm::vec3 t(int i, int j) const {
    const float* q = &tangent[4 * (i + j * nu)];
    return {q[0], q[1], q[2]};
  }
  float w(int i, int j) const { return tangent[4 * (i + j * nu) + 3]; }
  void compute() { compute_grid_tangents(nu, nv, pos.data(), normal.data(), tangent.data()); }

  // Area-weighted normals of GridCloth's triangulation ((i,j), (i+1,j), (i+1,j+1)) and
  // ((i,j), (i+1,j+1), (i,j+1)): the solver's orientation, along dP/du x dP/dv.
  void triangle_normals() {
    std::vector<glm::dvec3> acc(nu * nv, glm::dvec3(0.0));
    for (int j = 0; j + 1 < nv; ++j) {
      for (int i = 0; i + 1 < nu; ++i) {
        const int a = i + j * nu, b = a + 1, c = a + 1 + nu, d = a + nu;
        for (auto [x, y, z] : {std::array{a, b, c}, std::array{a, c, d}}) {
          const glm::dvec3 px(p(x % nu, x / nu)), py(p(y % nu, y / nu)), pz(p(z % nu, z / nu));
          const glm::dvec3 f = glm::cross(py - px, pz - px);
          acc[x] += f, acc[y] += f, acc[z] += f;
        }
      }
    }
    for (int v = 0; v < nu * nv; ++v) set_n(v % nu, v / nu, glm::vec3(glm::normalize(acc[v])));
  }
};

TEST(GridTangents, FlatGridInXZ) {
  // u along +x, v along +z; the triangles' normal x × z = -y, so the frame is right-handed.
  Grid g(9, 6);
  for (int j = 0; j < g.nv; ++j)
    for (int i = 0; i < g.nu; ++i) g.set_p(i, j, {0.1f * i - 0.3f, 1.5f, 0.2f * j});
  g.triangle_normals();
  EXPECT_EQ(g.n(4, 3), glm::vec3(0.0f, -1.0f, 0.0f));
  g.compute();
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      EXPECT_NEAR(g.t(i, j).x, 1.0f, 1e-6f);
      EXPECT_NEAR(g.t(i, j).y, 0.0f, 1e-6f);
      EXPECT_NEAR(g.t(i, j).z, 0.0f, 1e-6f);
      EXPECT_EQ(g.w(i, j), 1.0f);
    }
  }
  // The same sheet seen from the other side (flipped normals): T stays, the handedness flips.
  for (int j = 0; j < g.nv; ++j)
    for (int i = 0; i < g.nu; ++i) g.set_n(i, j, {0.0f, 1.0f, 0.0f});
  g.compute();
  EXPECT_NEAR(g.t(2, 2).x, 1.0f, 1e-6f);
  EXPECT_EQ(g.w(2, 2), -1.0f);
}

TEST(GridTangents, MirroredUFlipsHandedness) {
  // Built right to left: u runs along -x; the normal is the unmirrored sheet's -y.
  Grid g(7, 5);
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      g.set_p(i, j, {-0.1f * i, 0.0f, 0.1f * j});
      g.set_n(i, j, {0.0f, -1.0f, 0.0f});
    }
  }
  g.compute();
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      EXPECT_NEAR(g.t(i, j).x, -1.0f, 1e-6f);
      EXPECT_EQ(g.w(i, j), -1.0f);
      // B = w N × T still points along +v (+z).
      const glm::vec3 b = g.w(i, j) * glm::cross(g.n(i, j), g.t(i, j));
      EXPECT_NEAR(b.z, 1.0f, 1e-6f);
    }
  }
}

TEST(GridTangents, DeformedGridFrameIsOrthonormalWithDetW) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> jitter(-0.03f, 0.03f);
  Grid g(24, 17);
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      const float x = 0.05f * i, z = 0.05f * j;
      g.set_p(i, j,
              {x + jitter(rng), 0.2f * std::sin(7.0f * x) * std::cos(5.0f * z) + jitter(rng),
               z + jitter(rng)});
    }
  }
  g.triangle_normals();
  // A few flipped normals, as on a fold seen from behind: w must follow them.
  for (int k = 0; k < 10; ++k) {
    const int i = int(rng() % g.nu), j = int(rng() % g.nv);
    g.set_n(i, j, -g.n(i, j));
  }
  g.compute();
  int negative = 0;
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      const glm::vec3 t = g.t(i, j), n = g.n(i, j);
      const float w = g.w(i, j);
      ASSERT_TRUE(w == 1.0f || w == -1.0f);
      EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
      const glm::vec3 b = w * glm::cross(n, t);
      EXPECT_NEAR(glm::determinant(glm::mat3(t, b, n)), w, 1e-5f);
      // Handedness from the geometry: B goes along dP/dv and T along dP/du.
      const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, g.nu - 1);
      const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, g.nv - 1);
      EXPECT_GT(glm::dot(b, g.p(i, j1) - g.p(i, j0)), 0.0f) << i << "," << j;
      EXPECT_GT(glm::dot(t, g.p(i1, j) - g.p(i0, j)), 0.0f) << i << "," << j;
      negative += w < 0.0f;
    }
  }
  EXPECT_GT(negative, 0);
}

TEST(GridTangents, CylinderSectionMatchesAnalyticTangent) {
  // P(u, v) = (R sin θ, R cos θ, L v), θ = θ0 + Δθ u: dP/du ∝ (cos θ, -sin θ, 0); the
  // triangles' normal along dP/du × dP/dv is the inward radial direction -(sin θ, cos θ, 0).
  const int nu = 33, nv = 9;
  const double radius = 0.4, length = 1.0, theta0 = -0.5, dtheta = 1.1;
  Grid g(nu, nv);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double th = theta0 + dtheta * i / (nu - 1);
      g.set_p(i, j, glm::vec3(radius * std::sin(th), radius * std::cos(th), length * j / (nv - 1)));
      g.set_n(i, j, glm::vec3(-std::sin(th), -std::cos(th), 0.0));
    }
  }
  g.compute();
  double worst = 0.0;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double th = theta0 + dtheta * i / (nu - 1);
      const glm::dvec3 exact(std::cos(th), -std::sin(th), 0.0);
      const double c = std::clamp(glm::dot(glm::dvec3(g.t(i, j)), exact), -1.0, 1.0);
      worst = std::max(worst, std::acos(c) * 180.0 / M_PI);
      EXPECT_EQ(g.w(i, j), 1.0f);
    }
  }
  EXPECT_LT(worst, 2.0);
}

TEST(GridTangents, DegenerateCasesFallBackToAUnitOrthogonalVector) {
  // A grid collapsed along u (all columns at one place), a single column (nu == 1), and dP/du
  // parallel to N: T must still be unit and orthogonal to N, and the same for equal inputs.
  for (int nu : {1, 4}) {
    Grid g(nu, 5);
    for (int j = 0; j < g.nv; ++j) {
      for (int i = 0; i < g.nu; ++i) {
        g.set_p(i, j, {0.0f, 0.0f, 0.1f * j});
        g.set_n(i, j, glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f)));
      }
    }
    g.compute();
    for (int j = 0; j < g.nv; ++j) {
      for (int i = 0; i < g.nu; ++i) {
        EXPECT_NEAR(glm::length(g.t(i, j)), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(g.t(i, j), g.n(i, j)), 0.0f, 1e-5f);
        EXPECT_EQ(g.t(i, j), g.t(0, 0));
        // With dP/dv intact, B = w N × T still points along +v.
        EXPECT_GT((g.w(i, j) * glm::cross(g.n(i, j), g.t(i, j))).z, 0.99f);
      }
    }
  }
  Grid g(3, 1);  // one row, dP/du along N, no dP/dv: the fixed fallback
  for (int i = 0; i < 3; ++i) {
    g.set_p(i, 0, {0.0f, 0.2f * i, 0.0f});
    g.set_n(i, 0, {0.0f, 1.0f, 0.0f});
  }
  g.compute();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(glm::length(g.t(i, 0)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(g.t(i, 0), g.n(i, 0)), 0.0f, 1e-5f);
    EXPECT_FALSE(std::isnan(g.w(i, 0)));
  }
}

}  // namespace
}  // namespace clothlab
