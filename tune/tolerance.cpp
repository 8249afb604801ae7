#include "tune/tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <toml++/toml.h>

#include "sim/scene/scene_error.hpp"
#include "tune/toml_io.hpp"

namespace clothlab::tune {

TuneSummary summarize(const Result& result) {
  TuneSummary s;
  s.reference_error = result.reference.worst_self();
  s.reference = result.reference.setting;
  s.reference.family = "reference";
  for (const Row& r : result.rows) {
    Row kept = r;
    kept.error = {{r.worst_rms(), 0.0}};
    s.rows.push_back(std::move(kept));
  }
  return s;
}

std::string cache_directory() {
  if (const char* dir = std::getenv("CLOTHLAB_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/clothlab";
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : "/tmp") + "/.cache/clothlab";
}

namespace {

// FNV-1a, 64 bits (Fowler, Noll & Vo): a stable hash for the cache's file names.
std::uint64_t fnv1a(const std::string& text, std::uint64_t h = 14695981039346656037ull) {
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string processor() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line;
  return "unknown processor";
}

}  // namespace

std::string cache_file(const std::string& scene_text, const std::vector<std::string>& overrides) {
  // The tolerance is left out: every tolerance reads the same table.
  std::string key =
      std::regex_replace(scene_text, std::regex(R"((^|\n)[ \t]*tolerance[ \t]*=[^\n]*)"), "$1");
  for (const std::string& o : overrides)
    if (o.rfind("solver.tolerance=", 0) != 0) key += "\n--set " + o;
  key += "\n" + processor() + "\n" + std::to_string(std::thread::hardware_concurrency());
  char name[40];
  std::snprintf(name, sizeof name, "tune-%016llx.toml", (unsigned long long)fnv1a(key));
  return cache_directory() + "/" + name;
}

using toml_io::number;
using toml_io::setting_from;

std::optional<TuneSummary> read_summary(const std::string& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    const toml::table t = toml::parse_file(path);
    TuneSummary s;
    s.reference_error = number(t["reference_error"]);
    s.reference = setting_from(*t["reference"].as_table());
    for (const toml::node& n : *t["rows"].as_array()) {
      const toml::table& r = *n.as_table();
      Row row;
      row.setting = setting_from(r);
      row.error = {{number(r["worst_rms"]), 0.0}};
      row.cost = number(r["cost"]);
      row.status = r["status"].value_or(std::string("unreadable"));
      s.rows.push_back(std::move(row));
    }
    if (!std::isfinite(s.reference_error)) return std::nullopt;
    return s;
  } catch (const std::exception&) {  // a damaged entry is tuned again
    return std::nullopt;
  }
}

void write_summary(const std::string& path, const TuneSummary& s) {
  toml_io::write_atomically(path, [&](std::ostream& out) {
    out << "# clothlab tune to " << kToleranceHorizon << " s (docs/tuning.md): the cache of "
        << "solver.tolerance\nreference_error = " << toml_io::exact(s.reference_error)
        << "\n\n[reference]\n";
    toml_io::write_setting(out, s.reference);
    for (const Row& r : s.rows) {
      out << "\n[[rows]]\n";
      toml_io::write_setting(out, r.setting);
      out << "worst_rms = " << toml_io::exact(r.worst_rms())
          << "\ncost = " << toml_io::exact(r.cost)
          << "\nstatus = " << toml::value<std::string>(r.status) << "\n";
    }
  });
}

TolerancePick pick(const TuneSummary& summary, double tolerance) {
  char text[200];
  if (tolerance < summary.reference_error) {
    std::snprintf(text, sizeof text,
                  "%.3g mm is below the reference's own error to %g s on this scene (%.3g mm): "
                  "no setting can be shown to meet it",
                  1e3 * tolerance, kToleranceHorizon, 1e3 * summary.reference_error);
    throw std::invalid_argument(text);
  }
  TolerancePick p;
  if (const auto best = cheapest_within(summary.rows, tolerance)) {
    const Row& r = summary.rows[*best];
    p.setting = r.setting, p.worst_rms = r.worst_rms(), p.cost = r.cost;
    std::snprintf(text, sizeof text,
                  "%s, the cheapest of the tune within %.3g mm to %g s (%.3g mm, %.3g s per "
                  "simulated s)",
                  r.setting.label.c_str(), 1e3 * tolerance, kToleranceHorizon, 1e3 * p.worst_rms,
                  p.cost);
  } else {
    p.setting = summary.reference, p.worst_rms = summary.reference_error, p.reference = true;
    std::snprintf(text, sizeof text,
                  "%s: the reference, as no setting of the tune is within %.3g mm to %g s",
                  summary.reference.label.c_str(), 1e3 * tolerance, kToleranceHorizon);
  }
  p.why = text;
  return p;
}

TolerancePick resolve_tolerance(const SceneReader& read, const std::string& cache_path,
                                double tolerance, std::ostream* log) {
  std::optional<TuneSummary> summary = read_summary(cache_path);
  const bool cached = summary.has_value();
  if (!summary) {
    Options o;
    o.duration = kToleranceHorizon;
    o.log = log;
    summary = summarize(run_tune(read, o));
    write_summary(cache_path, *summary);
  }
  TolerancePick p = pick(*summary, tolerance);
  p.cached = cached;
  return p;
}

TolerancePick resolve_scene_tolerance(const SceneReader& read, const Scene& scene,
                                      const std::string& file, const std::string& cache_path,
                                      std::ostream* log) {
  const std::string key = "solver.tolerance";
  const auto at = scene.locations.find(key);
  const SourceLoc where = at != scene.locations.end() ? at->second : SourceLoc{file, 0, 0};
  try {
    return resolve_tolerance(read, cache_path, scene.solver.tolerance, log);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where, key, e.what());
  } catch (const std::runtime_error& e) {  // a reference that diverges, a cache not written
    throw SceneError(where, key, std::string("the scene cannot be tuned: ") + e.what());
  }
}

}  // namespace clothlab::tune
