// `clothlab bench --suite contact`: cloth against cloth on the contact stress scenes and on the
// large sheet that never touches itself, with triangle contact (solver.cloth_contact) on and off
// on `--threads` solver threads (the targets are stated for 2): the largest count of crossing
// edge/triangle pairs over the 60 Hz frames (sim/contact/intersections.hpp), the count at the end,
// the time a 1/60 s frame takes (the count is not timed) and its ratio to the same scene without
// contact, the time a frame takes over the run's slowest second (a landing or an impact: where a
// scene that keeps real time on average still stutters), and what contact did in its last pass
// (pairs, pushes, and the triangles its flat patches skipped). docs/contact.md section 7 quotes it.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench/suites/suites.hpp"
#include "load/scene_load.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {
namespace {

struct ContactCase {
  std::string scene;  // file in scenes/
  double seconds = 0.0;
  double quick_seconds = 0.0;  // 0: left out of --quick
};

struct ContactRun {
  long worst = 0, end = 0;
  double frame_ms = 0.0;
  double slowest_second_ms = 0.0;  // the mean over the 60 consecutive frames that took longest
  int candidates = 0, contacts = 0, flat_triangles = 0;
};

ContactRun run_case(const std::string& path, bool contact, double seconds, int threads) {
  const Scene scene =
      read_scene_file(path, {std::string("solver.cloth_contact=") + (contact ? "true" : "false"),
                             "solver.threads=" + std::to_string(threads)});
  std::unique_ptr<Solver> s = make_solver(scene);
  ContactRun r;
  const int frames = int(seconds * 60.0 + 0.5);
  std::vector<double> times;
  times.reserve(std::size_t(frames));
  for (int f = 0; f < frames; ++f) {
    Stopwatch watch;
    if (!s->advance(1.0 / 60.0).ok()) break;
    times.push_back(watch.seconds());
    r.worst = std::max(r.worst, s->intersections());
  }
  r.end = s->intersections();
  double stepping = 0.0;
  for (double t : times) stepping += t;
  r.frame_ms = frames > 0 ? 1e3 * stepping / frames : 0.0;
  r.slowest_second_ms = 1e3 * slowest_window_mean(times, 60);
  if (const auto c = s->last_cloth_contact()) {
    r.candidates = c->candidates;
    r.contacts = c->contacts;
    r.flat_triangles = c->flat_triangles;
  }
  return r;
}

}  // namespace

std::vector<Table> contact_suite(const SuiteOptions& o) {
  const std::filesystem::path scenes = std::filesystem::path(CLOTHLAB_DEFAULT_SCENE).parent_path();
  const std::vector<ContactCase> cases = {{"pile.toml", 5.0, 2.5},
                                          {"stack_on_ball.toml", 3.0, 0.5},
                                          {"thin_table.toml", 5.0, 1.0},
                                          {"large_sheet.toml", 1.0, 0.0}};
  Table t{"",
          "Cloth against cloth: crossing edge/triangle pairs over the 60 Hz frames and the cost "
          "of triangle contact (" +
              std::to_string(o.threads) + " solver threads)",
          quick_note(o.quick, "the 256 x 256 large sheet, and most of each run"),
          {"scene", "cloth_contact", "vertices", "seconds", "worst crossings", "crossings at end",
           "ms a frame", "cost vs off", "ms a frame, slowest second", "candidate pairs",
           "pushed apart", "triangles in flat patches"},
          {}};
  for (const ContactCase& c : cases) {
    const double seconds = o.quick ? c.quick_seconds : c.seconds;
    if (seconds <= 0.0) continue;
    const std::string path = (scenes / c.scene).string();
    const std::size_t vertices = make_solver(read_scene_file(path))->vertex_count();
    double off_ms = 0.0;
    for (bool contact : {false, true}) {
      if (o.log) *o.log << "contact: " << c.scene << (contact ? " on" : " off") << "\n";
      const ContactRun r = run_case(path, contact, seconds, o.threads);
      if (!contact) off_ms = r.frame_ms;
      t.add({c.scene, contact ? "true" : "false", std::to_string(vertices), num(seconds),
             std::to_string(r.worst), std::to_string(r.end), num(r.frame_ms),
             num(off_ms > 0.0 ? r.frame_ms / off_ms : 0.0), num(r.slowest_second_ms),
             std::to_string(r.candidates), std::to_string(r.contacts),
             std::to_string(r.flat_triangles)});
    }
  }
  return {t};
}

}  // namespace clothlab::bench
