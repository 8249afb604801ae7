// `clothlab tune`: the work-precision table of the user's own scene (tune/tune.hpp,
// docs/tuning.md), its frontier, a CSV and a PNG plot, and the cheapest setting within the
// tolerance as --set lines and as TOML to paste into the scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/remote_tune.hpp"
#include "bench/suites/report.hpp"
#include "sim/scene/scene_error.hpp"
#include "tune/work_precision_plot.hpp"

namespace clothlab::app {

namespace {

// Millimetres to three significant digits, as people read them.
std::string mm(double metres) {
  if (!std::isfinite(metres)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", 1e3 * metres);
  return text;
}

// A number as it is (%.17g): the CSV's values read back to the same doubles.
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// One row per candidate and sample time, exact values for notebooks.
bench::Table data_table(const tune::Result& r) {
  bench::Table t;
  t.title = "tune: every setting against the reference";
  t.columns = {"setting",
               "family",
               "time (s)",
               "rms error (m)",
               "max error (m)",
               "energy drift (J)",
               "wall per simulated s (s)",
               "frontier",
               "status",
               "set"};
  const std::vector<std::size_t> front = tune::frontier(r.rows);
  const auto joined = [](const tune::Setting& s) {
    std::string out;
    for (const std::string& o : s.overrides) out += (out.empty() ? "" : " ") + o;
    return out;
  };
  for (std::size_t k = 0; k < r.times.size(); ++k)
    t.add({r.reference.setting.label, "reference", exact(r.times[k]),
           exact(r.reference.self[k].rms), exact(r.reference.self[k].max), "0",
           exact(r.reference.cost), "-", "reference (its error: distance from half its step)",
           joined(r.reference.setting)});
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const tune::Row& row = r.rows[i];
    const bool on = std::find(front.begin(), front.end(), i) != front.end();
    for (std::size_t k = 0; k < std::max<std::size_t>(row.error.size(), 1); ++k) {
      const bool has = k < row.error.size();
      t.add({row.setting.label, row.setting.family, has ? exact(r.times[k]) : "-",
             has ? exact(row.error[k].rms) : "-", has ? exact(row.error[k].max) : "-",
             has ? exact(row.energy_drift) : "-", exact(row.cost), on ? "yes" : "no", row.status,
             joined(row.setting)});
    }
  }
  return t;
}

// One row per candidate for people: RMS in mm at each time, cost, and the frontier marked.
bench::Table people_table(const tune::Result& r) {
  bench::Table t;
  t.title =
      "tune: RMS distance from the reference (mm) at each time; cost = wall s per "
      "simulated s; * = on the frontier";
  t.columns = {"setting"};
  for (double time : r.times) {
    char head[32];
    std::snprintf(head, sizeof head, "at %.3g s", time);
    t.columns.push_back(head);
  }
  t.columns.insert(t.columns.end(), {"energy drift (J)", "cost (s/s)", "status"});
  const std::vector<std::size_t> front = tune::frontier(r.rows);
  std::vector<std::string> ref = {"reference: " + r.reference.setting.label};
  for (const tune::Distance& d : r.reference.self) ref.push_back("<= " + mm(d.rms));
  ref.insert(ref.end(), {"0", bench::num(r.reference.cost), "ok"});
  t.add(ref);
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const tune::Row& row = r.rows[i];
    const bool on = std::find(front.begin(), front.end(), i) != front.end();
    std::vector<std::string> cells = {(on ? "* " : "  ") + row.setting.label};
    for (std::size_t k = 0; k < r.times.size(); ++k)
      cells.push_back(k < row.error.size() ? mm(row.error[k].rms) : "-");
    cells.insert(cells.end(), {row.error.empty() ? "-" : bench::num(row.energy_drift),
                               std::isfinite(row.cost) ? bench::num(row.cost) : "-", row.status});
    t.add(cells);
  }
  return t;
}

void print_recommendation(const tune::Result& r, double tolerance) {
  const auto best = tune::cheapest_within(r.rows, tolerance);
  std::printf("\nwithin %s mm RMS up to %g s: ", mm(tolerance).c_str(), r.times.back());
  if (tolerance < r.reference.worst_self()) {
    std::printf(
        "cannot be told: the reference itself is only good to %s mm (ask for a larger "
        "tolerance, or a shorter --duration, over which the reference is more accurate)\n",
        mm(r.reference.worst_self()).c_str());
    return;
  }
  if (!best) {
    std::printf(
        "no setting of the ladder is that accurate; the reference is (%.3g s per "
        "simulated s):\n",
        r.reference.cost);
    for (const std::string& o : r.reference.setting.overrides)
      std::printf("  --set %s\n", o.c_str());
    return;
  }
  const tune::Row& row = r.rows[*best];
  std::printf("%s, %s mm at worst, %.3g s per simulated s (%s real time)\n",
              row.setting.label.c_str(), mm(row.worst_rms()).c_str(), row.cost,
              row.cost <= 1.0 ? "faster than" : "slower than");
  for (const std::string& o : row.setting.overrides) std::printf("  --set %s\n", o.c_str());
  std::printf("or in the scene:\n%s", tune::as_toml(row.setting).c_str());
}

std::filesystem::path csv_path(const TuneArgs& args) {
  if (!args.out.empty()) return args.out;
  return std::filesystem::path("out/tune") /
         (std::filesystem::path(args.scene).stem().string() + ".csv");
}

}  // namespace

int run_tune_command(const TuneArgs& args) {
  if (!load_scene("tune", args.scene, args.overrides)) return kBadInput;
  tune::Options o;
  o.duration = args.duration;
  o.threads = args.threads;
  o.log = args.quiet ? nullptr : &std::cerr;
  tune::Result result;
  if (!args.scheduler.empty()) {
    RemoteTune remote = tune_on_scheduler(args);
    if (!remote.result) return remote.status;
    result = std::move(*remote.result);
  } else {
    try {
      result = tune::run_tune(tune::file_reader(args.scene, args.overrides), o);
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "clothlab tune: %s\n", e.what());
      return 1;
    }
  }
  bench::print_table(std::cout, people_table(result));
  std::vector<double> tolerances = {0.06, 0.02, 0.005};
  if (args.tolerance) tolerances = {*args.tolerance};
  for (double tol : tolerances) print_recommendation(result, tol);
  const std::filesystem::path csv = csv_path(args);
  std::filesystem::path png = csv;
  png.replace_extension(".png");
  tune::PlotLabels labels;
  labels.title = std::filesystem::path(args.scene).filename().string() +
                 " to T = " + bench::num(result.times.back()) + " s";
  labels.tolerance = args.tolerance;
  if (args.tolerance) labels.chosen = tune::cheapest_within(result.rows, *args.tolerance);
  try {
    bench::write_csv(csv.string(), data_table(result));
    tune::write_work_precision_plot(result, labels, png.string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clothlab tune: %s\n", e.what());
    return 1;
  }
  std::printf("\nwrote %s and %s\n", csv.string().c_str(), png.string().c_str());
  return 0;
}

}  // namespace clothlab::app
