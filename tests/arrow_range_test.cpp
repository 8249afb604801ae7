// The force arrows' automatic scale (vis/render/arrow_field.hpp), without a GL context: at the
// default sheet's rest most sampled vertices draw a visible arrow, and the range's top is a
// robust quantile that one outlier does not move.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/solver.hpp"
#include "vis/render/arrow_field.hpp"

namespace clothlab {
namespace {

std::vector<float> force_vectors(Solver& s, ForceSource source) {
  s.update_force_field(source);
  std::vector<float> out(3 * s.vertex_count());
  for (std::size_t v = 0; v < s.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) out[3 * v + k] = static_cast<float>(s.force(int(v))[k]);
  return out;
}

// The share of the layout's free vertices whose arrow is at least a quarter of the longest: at
// the default camera the longest is about 12 px (0.9 of the 8 cm spacing), so a quarter is 3 px.
double share_visible(Solver& s, ForceSource source) {
  const vis::ArrowLayout layout = vis::arrow_layout(s, 0);
  std::vector<float> positions(3 * s.vertex_count());
  s.copy_positions(positions.data());
  const std::vector<float> vectors = force_vectors(s, source);
  const vis::ScalarRange range =
      vis::arrow_range(s, layout, vectors, vis::RangeMode::automatic, {});
  std::vector<vis::ArrowInstance> arrows;
  vis::build_force_arrows(layout, positions, vectors, vis::ArrowScale::linear, 1.0f, range, arrows);
  int free = 0, visible = 0;
  for (std::size_t k = 0; k < arrows.size(); ++k) {
    if (s.pinned(layout.vertices[k])) continue;
    ++free;
    visible += glm::length(arrows[k].vector) >= 0.25f;
  }
  return double(visible) / double(free);
}

// The default sheet hanging still (its wind off, 4 s to settle): the total force is the small
// residue of the springs against gravity, largest beside the pins. Sized by the 0.9 quantile
// of the free magnitudes at least 80 % of the arrows show (3 px or more) for the total and for
// the spring forces alike; sized by the largest, as before, a few near the pins did.
TEST(ForceArrows, MostArrowsShowAtTheDefaultSheetsRest) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/default.toml"));
  scene.forces.wind.enabled = false;
  std::unique_ptr<Solver> s = make_solver(scene);
  ASSERT_TRUE(s->advance(4.0).ok());
  EXPECT_GE(share_visible(*s, ForceSource::total), 0.8);
  EXPECT_GE(share_visible(*s, ForceSource::springs), 0.8);
}

// One outlier (a thousand times the rest) leaves the range's top where the others put it.
TEST(ForceArrows, RangeTopIgnoresOneOutlier) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/default.toml"));
  std::unique_ptr<Solver> s = make_solver(scene);
  const vis::ArrowLayout layout = vis::arrow_layout(*s, 0);
  std::vector<float> vectors(3 * s->vertex_count(), 0.0f);
  for (std::size_t k = 0; k < layout.vertices.size(); ++k)
    vectors[3 * std::size_t(layout.vertices[k]) + 1] = 1.0f + float(k % 10) / 10.0f;
  const int outlier = layout.vertices[layout.vertices.size() / 2];
  vectors[3 * std::size_t(outlier) + 1] = 1000.0f;
  const vis::ScalarRange range =
      vis::arrow_range(*s, layout, vectors, vis::RangeMode::automatic, {});
  EXPECT_GE(range.max, 1.79);
  EXPECT_LE(range.max, 1.9);
  const vis::ScalarRange fixed =
      vis::arrow_range(*s, layout, vectors, vis::RangeMode::fixed, {0.0, 5.0});
  EXPECT_EQ(fixed.max, 5.0);
}

}  // namespace
}  // namespace clothlab
