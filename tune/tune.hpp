// `clothlab tune`: run time against error on the user's own scene (docs/tuning.md). The scene's
// reference (RK4 in double at half its stability limit, and again at half that step; the finer
// run is the reference, and the two runs' distance bounds its own error) and a ladder of
// candidate settings (tune/ladder.hpp) are run from the same scene file, contact, pins, wind and
// music included; every candidate is measured against the reference at sample times up to the
// horizon (RMS and largest distance over all vertices, energy) with its wall time per simulated
// second. The cheapest candidate whose RMS stays within a tolerance at every sample time is the
// recommendation; the frontier is the candidates no cheaper one beats.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "tune/sampled_run.hpp"

namespace clothlab::tune {

struct Options {
  double duration = 1.0;            // s: the horizon T
  int samples = 4;                  // sample times T k / samples, rounded to frames
  int threads = 0;                  // solver.threads for every run; 0: the scene's own
  double reference_fraction = 0.5;  // of RK4's stability limit, the coarser reference step
  std::ostream* log = nullptr;      // a progress line per run
};

// One candidate measured against the reference.
struct Row {
  Setting setting;
  std::vector<Distance> error;  // m, at each sample time it reached
  double energy_drift = 0.0;  // J: its total energy less the reference's, at the last time reached
  double cost = 0.0;          // s of wall time per simulated second (of the part it ran)
  std::string status = "ok";  // ok, or why it has no result: diverged, stopped, not applicable
  bool ok() const { return status == "ok"; }
  // m: the largest RMS over the sample times; infinite unless it finished.
  double worst_rms() const;
};

struct Reference {
  Setting setting;             // the finer run's
  SampledRun run;              // the finer run: what every candidate is measured against
  std::vector<Distance> self;  // m: its distance from the coarser run at each time, its error bound
  double cost = 0.0;           // s per simulated second
  // s: how long a candidate may run: twice the coarser run's wall time, the finer run's
  // expected one, known before the finer run ends (so that candidates can start beside it).
  double stop_after = 0.0;
  double worst_self() const;  // m: the largest self RMS
};

struct Result {
  std::vector<double> times;
  Reference reference;
  std::vector<Row> rows;
};

// Reads the user's scene with some --set lines added after the user's own (the Python module's
// Scene and the command line's file both give one). Throws SceneError.
using SceneReader = std::function<Scene(const std::vector<std::string>& extra)>;

// The reader of `scene_path` with the user's `overrides`, then the extra lines.
SceneReader file_reader(const std::string& scene_path, const std::vector<std::string>& overrides);

// T k / samples for k = 1..samples, each rounded to a whole frame (at least one frame, distinct).
std::vector<double> sample_times(double duration, int samples);

// The scene of one setting: the reader's, then the CPU backend and the options' thread count,
// then the setting's own lines.
Scene setting_scene(const SceneReader& read, const Options& options, const Setting& setting);

// The settings a tune runs, from the scene's spectrum (tune/ladder.hpp): the reference at its
// coarser step and at its own, and the ladder.
struct Settings {
  Setting coarse, reference;
  std::vector<Setting> ladder;
};
Settings settings_for(const SceneReader& read, const Options& options);

// The reference from its two runs: `fine` measured against `coarse` at each time. Throws
// std::runtime_error naming the run when either did not finish.
Reference make_reference(const Settings& settings, SampledRun fine, const SampledRun& coarse,
                         const std::vector<double>& times);

// What a tune needs before its candidates run: the sample times, the reference run and the
// ladder. Throws SceneError when the scene is not valid, std::runtime_error when its reference
// diverges.
struct Plan {
  std::vector<double> times;
  Reference reference;
  std::vector<Setting> ladder;
};
Plan plan_tune(const SceneReader& read, const Options& options);

// One setting run to `times`, stopped once it takes longer than `wall_limit` s (0: never). Never
// throws for a bad case: a setting that does not make a valid scene is a run whose failure says
// "not applicable: " and why.
SampledRun run_setting(const SceneReader& read, const Options& options, const Setting& setting,
                       const std::vector<double>& times, double wall_limit);

// A setting's run against the reference run at `times`.
Row row_from(const Setting& setting, const SampledRun& run, const SampledRun& reference,
             const std::vector<double>& times);

// run_setting, then row_from.
Row measure(const SceneReader& read, const Options& options, const Setting& setting,
            const SampledRun& reference, const std::vector<double>& times, double wall_limit);

// plan_tune, then every candidate of the ladder in order, each stopped once it takes longer
// than the reference is expected to (Reference::stop_after; the reference would then be cheaper
// and more accurate).
Result run_tune(const SceneReader& read, const Options& options);

// Row indices on the frontier, by cost: each finished row that no cheaper finished row matches
// or beats in worst RMS.
std::vector<std::size_t> frontier(const std::vector<Row>& rows);

// The cheapest finished row whose worst RMS is within `tolerance` (m), if any.
std::optional<std::size_t> cheapest_within(const std::vector<Row>& rows, double tolerance);

// The --set lines as TOML to paste into a scene: "[solver]" and its keys.
std::string as_toml(const Setting& setting);

}  // namespace clothlab::tune
