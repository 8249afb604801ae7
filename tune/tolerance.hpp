// solver.tolerance (docs/tuning.md, "A tolerance in the scene"): a scene asks for an accuracy
// instead of a step. Its tune to 1 s is kept in the user's cache directory, keyed by the scene's
// text and overrides (the tolerance itself left out, so that another tolerance reads the same
// entry) and by the machine, and the cheapest setting within the tolerance is read from it; a
// scene without an entry is tuned first. The chosen setting's --set lines are then added to the
// scene's own.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "tune/tune.hpp"

namespace clothlab::tune {

inline constexpr double kToleranceHorizon = 1.0;  // s: the horizon solver.tolerance holds to

// What a cache entry keeps of a tune: every finished or failed setting and the reference's bound.
struct TuneSummary {
  double reference_error = 0.0;  // m: the reference's worst RMS bound
  Setting reference;             // used when no setting of the ladder is within the tolerance
  std::vector<Row> rows;         // error only as worst_rms in error[0]
};

TuneSummary summarize(const Result& result);

// The folder: $CLOTHLAB_CACHE_DIR, else $XDG_CACHE_HOME/clothlab, else $HOME/.cache/clothlab.
std::string cache_directory();

// The entry's file for a scene: a hash of its text and overrides without any solver.tolerance
// line, of the machine's processor and core count, and of the thread count asked for.
std::string cache_file(const std::string& scene_text, const std::vector<std::string>& overrides);

// Reads an entry (nothing when missing or unreadable) and writes one (complete or absent;
// throws std::runtime_error naming the file on failure).
std::optional<TuneSummary> read_summary(const std::string& path);
void write_summary(const std::string& path, const TuneSummary& summary);

// What solver.tolerance chose, and why.
struct TolerancePick {
  Setting setting;
  double worst_rms = 0.0;  // m, to kToleranceHorizon
  double cost = 0.0;       // s per simulated second when tuned
  bool reference = false;  // no setting of the ladder was within: the reference's own
  bool cached = false;     // read from the cache rather than tuned now
  std::string why;         // one line for people
};

// The cheapest setting within `tolerance` m of `summary`. Throws std::invalid_argument with the
// reason when the tolerance is below the reference's own error.
TolerancePick pick(const TuneSummary& summary, double tolerance);

// The setting for a scene whose solver.tolerance is `tolerance`: from the entry at `cache_path`,
// else from a tune to kToleranceHorizon (progress to `log`), which is then kept there. Throws as
// pick() does, and as run_tune() does for a scene whose reference diverges.
TolerancePick resolve_tolerance(const SceneReader& read, const std::string& cache_path,
                                double tolerance, std::ostream* log);

// resolve_tolerance for `scene`'s solver.tolerance, with every failure a SceneError at that key
// (at `file` when the key has no location): what the commands and the Python module call.
TolerancePick resolve_scene_tolerance(const SceneReader& read, const Scene& scene,
                                      const std::string& file, const std::string& cache_path,
                                      std::ostream* log);

}  // namespace clothlab::tune
