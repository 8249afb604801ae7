#include "tune/tune.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>

#include <toml++/toml.h>

#include "load/scene_load.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/stability/spectrum.hpp"
#include "tune/ladder.hpp"

namespace clothlab::tune {

double Row::worst_rms() const {
  if (!ok()) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (const Distance& d : error) worst = std::max(worst, d.rms);
  return worst;
}

double Reference::worst_self() const {
  double worst = 0.0;
  for (const Distance& d : self) worst = std::max(worst, d.rms);
  return worst;
}

std::vector<double> sample_times(double duration, int samples) {
  std::vector<double> times;
  long last = 0;
  for (int k = 1; k <= samples; ++k) {
    const long frames = std::max(1L, std::lround(duration * k / samples / kFrame));
    if (frames > last) times.push_back(double(frames) * kFrame);
    last = std::max(last, frames);
  }
  return times;
}

SceneReader file_reader(const std::string& scene_path, const std::vector<std::string>& overrides) {
  return [scene_path, overrides](const std::vector<std::string>& extra) {
    std::vector<std::string> all = overrides;
    all.insert(all.end(), extra.begin(), extra.end());
    return read_scene_file(scene_path, all);
  };
}

Scene setting_scene(const SceneReader& read, const Options& o, const Setting& setting) {
  std::vector<std::string> all = {"solver.backend=cpu"};
  if (o.threads > 0) all.push_back("solver.threads=" + std::to_string(o.threads));
  all.insert(all.end(), setting.overrides.begin(), setting.overrides.end());
  return read(all);
}

Settings settings_for(const SceneReader& read, const Options& o) {
  const Spectrum spectrum = estimate_spectrum(build_model<double>(setting_scene(read, o, {})));
  return {reference_setting(spectrum, o.reference_fraction, false),
          reference_setting(spectrum, o.reference_fraction, true), ladder(spectrum)};
}

Reference make_reference(const Settings& s, SampledRun fine, const SampledRun& coarse,
                         const std::vector<double>& times) {
  if (!coarse.finished())
    throw std::runtime_error("the reference (" + s.coarse.label + ") " + coarse.failure);
  if (!fine.finished())
    throw std::runtime_error("the reference (" + s.reference.label + ") " + fine.failure);
  Reference ref;
  ref.setting = s.reference;
  ref.run = std::move(fine);
  for (std::size_t k = 0; k < times.size(); ++k)
    ref.self.push_back(distance(ref.run.at[k], coarse.at[k]));
  ref.cost = ref.run.wall / times.back();
  ref.stop_after = 2.0 * coarse.wall;
  return ref;
}

SampledRun run_setting(const SceneReader& read, const Options& o, const Setting& setting,
                       const std::vector<double>& times, double wall_limit) {
  try {
    return run_sampled(setting_scene(read, o, setting), times, wall_limit);
  } catch (const std::exception& e) {  // a SceneError: the combination is not a valid scene
    SampledRun run;
    run.failure = std::string("not applicable: ") + e.what();
    return run;
  }
}

Row row_from(const Setting& setting, const SampledRun& run, const SampledRun& reference,
             const std::vector<double>& times) {
  Row row;
  row.setting = setting;
  for (std::size_t k = 0; k < run.at.size(); ++k)
    row.error.push_back(distance(run.at[k], reference.at[k]));
  if (!run.energy.empty())
    row.energy_drift = run.energy.back() - reference.energy[run.energy.size() - 1];
  const double simulated = run.at.empty() ? 0.0 : times[run.at.size() - 1];
  row.cost = simulated > 0.0 ? run.wall / simulated : std::numeric_limits<double>::infinity();
  if (!run.finished()) row.status = run.failure;
  return row;
}

Row measure(const SceneReader& read, const Options& o, const Setting& setting,
            const SampledRun& reference, const std::vector<double>& times, double wall_limit) {
  return row_from(setting, run_setting(read, o, setting, times, wall_limit), reference, times);
}

Plan plan_tune(const SceneReader& read, const Options& o) {
  Plan plan;
  plan.times = sample_times(o.duration, o.samples);
  Settings s = settings_for(read, o);
  const SampledRun coarse = run_sampled(setting_scene(read, o, s.coarse), plan.times, 0.0);
  if (o.log) *o.log << "tune: reference " << s.coarse.label << ": " << coarse.wall << " s\n";
  SampledRun fine = run_sampled(setting_scene(read, o, s.reference), plan.times, 0.0);
  plan.reference = make_reference(s, std::move(fine), coarse, plan.times);
  if (o.log)
    *o.log << "tune: reference " << s.reference.label << ": " << plan.reference.run.wall
           << " s, its own error at most " << 1e3 * plan.reference.worst_self() << " mm RMS\n";
  plan.ladder = std::move(s.ladder);
  return plan;
}

Result run_tune(const SceneReader& read, const Options& o) {
  Plan plan = plan_tune(read, o);
  Result result;
  result.times = plan.times;
  result.reference = std::move(plan.reference);
  const std::size_t n = plan.ladder.size();
  for (std::size_t i = 0; i < n; ++i) {
    result.rows.push_back(measure(read, o, plan.ladder[i], result.reference.run, result.times,
                                  result.reference.stop_after));
    const Row& r = result.rows.back();
    if (o.log)
      *o.log << "tune: [" << i + 1 << "/" << n << "] " << r.setting.label << ": "
             << (r.ok() ? std::to_string(1e3 * r.worst_rms()) + " mm RMS at worst, " +
                              std::to_string(r.cost) + " s per simulated s"
                        : r.status)
             << "\n";
  }
  return result;
}

std::vector<std::size_t> frontier(const std::vector<Row>& rows) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].ok()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a].cost < rows[b].cost; });
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i : order)
    if (rows[i].worst_rms() < best) {
      front.push_back(i);
      best = rows[i].worst_rms();
    }
  return front;
}

std::optional<std::size_t> cheapest_within(const std::vector<Row>& rows, double tolerance) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].ok() && rows[i].worst_rms() <= tolerance &&
        (!best || rows[i].cost < rows[*best].cost))
      best = i;
  return best;
}

std::string as_toml(const Setting& setting) {
  std::string out = "[solver]\n";
  for (const std::string& line : setting.overrides) {
    const std::size_t eq = line.find('=');
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    const std::string name = key.substr(key.find('.') + 1);
    bool is_toml = true;
    try {
      (void)toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
      is_toml = false;
    }
    out += name + " = " + (is_toml ? value : "\"" + value + "\"") + "\n";
  }
  return out;
}

}  // namespace clothlab::tune
