// The pieces of `clothlab tune` (tune/tune.hpp) that python/clothlab/tune.py runs as separate
// tasks, on this machine or on a Dask cluster: the settings from a scene's spectrum, one run to
// the sample times (a task), a run measured against the reference's (on the client), and the
// frontier and recommendation of a table. Settings and rows cross as dicts, positions as numpy
// arrays; the whole table can be written for the command line to read back.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings/bindings.hpp"
#include "tune/result_file.hpp"
#include "tune/tune.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

tune::SceneReader reader_of(const SceneSource& source) {
  return [source](const std::vector<std::string>& extra) {
    SceneSource s = source;
    s.overrides.insert(s.overrides.end(), extra.begin(), extra.end());
    return s.load();
  };
}

namespace {

tune::Options options_of(int threads) {
  tune::Options o;
  o.threads = threads;
  return o;
}

py::dict setting_dict(const tune::Setting& s) {
  py::dict d;
  d["family"] = s.family, d["label"] = s.label, d["overrides"] = s.overrides;
  return d;
}

tune::Setting setting_of(const py::dict& d) {
  return {d["family"].cast<std::string>(), d["label"].cast<std::string>(),
          d["overrides"].cast<std::vector<std::string>>()};
}

// (times, vertices, 3) doubles.
py::array_t<double> positions_array(const std::vector<tune::Positions>& at) {
  const std::size_t n = at.empty() ? 0 : at.front().size();
  py::array_t<double> a({at.size(), n, std::size_t(3)});
  auto w = a.mutable_unchecked<3>();
  for (std::size_t k = 0; k < at.size(); ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < 3; ++c) w(k, i, c) = at[k][i][c];
  return a;
}

tune::SampledRun run_of(const py::array_t<double>& positions, const std::vector<double>& energy) {
  tune::SampledRun run;
  const auto r = positions.unchecked<3>();
  for (py::ssize_t k = 0; k < r.shape(0); ++k) {
    tune::Positions p(std::size_t(r.shape(1)));
    for (py::ssize_t i = 0; i < r.shape(1); ++i)
      p[std::size_t(i)] = {r(k, i, 0), r(k, i, 1), r(k, i, 2)};
    run.at.push_back(std::move(p));
  }
  run.energy = energy;
  return run;
}

py::dict run_dict(const tune::SampledRun& run) {
  py::dict d;
  d["positions"] = positions_array(run.at), d["energy"] = run.energy, d["wall"] = run.wall;
  d["failure"] = run.failure;
  return d;
}

py::dict row_dict(const tune::Row& r) {
  py::dict d = setting_dict(r.setting);
  std::vector<double> rms, max;
  for (const tune::Distance& e : r.error) rms.push_back(e.rms), max.push_back(e.max);
  d["rms"] = rms, d["max"] = max, d["energy_drift"] = r.energy_drift, d["cost"] = r.cost;
  d["status"] = r.status;
  return d;
}

tune::Row row_of(const py::dict& d) {
  tune::Row r;
  r.setting = setting_of(d);
  const auto rms = d["rms"].cast<std::vector<double>>();
  const auto max = d["max"].cast<std::vector<double>>();
  for (std::size_t k = 0; k < rms.size(); ++k) r.error.push_back({rms[k], max[k]});
  r.energy_drift = d["energy_drift"].cast<double>();
  r.cost = d["cost"].cast<double>();
  r.status = d["status"].cast<std::string>();
  return r;
}

py::dict tune_settings(const SceneSource& scene, int threads) {
  const tune::Settings s = tune::settings_for(reader_of(scene), options_of(threads));
  py::list ladder;
  for (const tune::Setting& l : s.ladder) ladder.append(setting_dict(l));
  py::dict d;
  d["coarse"] = setting_dict(s.coarse), d["reference"] = setting_dict(s.reference);
  d["ladder"] = ladder;
  return d;
}

py::dict tune_run(const SceneSource& scene, const py::dict& setting,
                  const std::vector<double>& times, int threads, double wall_limit) {
  const tune::Setting s = setting_of(setting);
  tune::SampledRun r;
  {
    py::gil_scoped_release free;
    r = tune::run_setting(reader_of(scene), options_of(threads), s, times, wall_limit);
  }
  return run_dict(r);
}

py::dict tune_row(const py::dict& setting, const py::dict& run, const py::dict& reference,
                  const std::vector<double>& times) {
  tune::SampledRun r = run_of(run["positions"].cast<py::array_t<double>>(),
                              run["energy"].cast<std::vector<double>>());
  r.wall = run["wall"].cast<double>();
  r.failure = run["failure"].cast<std::string>();
  const tune::SampledRun ref = run_of(reference["positions"].cast<py::array_t<double>>(),
                                      reference["energy"].cast<std::vector<double>>());
  return row_dict(tune::row_from(setting_of(setting), r, ref, times));
}

py::dict pick(const py::list& rows, std::optional<double> tolerance) {
  std::vector<tune::Row> table;
  for (const py::handle& r : rows) table.push_back(row_of(r.cast<py::dict>()));
  py::dict d;
  d["frontier"] = tune::frontier(table);
  d["chosen"] = tolerance ? py::cast(tune::cheapest_within(table, *tolerance)) : py::none();
  return d;
}

// The whole table as the command line reads it back (`clothlab tune --scheduler`).
void write_result(const std::string& path, const std::vector<double>& times,
                  const py::dict& reference, const std::vector<std::pair<double, double>>& self,
                  double reference_cost, double stop_after, const py::list& rows) {
  tune::Result r;
  r.times = times;
  r.reference.setting = setting_of(reference);
  for (const auto& [rms, max] : self) r.reference.self.push_back({rms, max});
  r.reference.cost = reference_cost;
  r.reference.stop_after = stop_after;
  for (const py::handle& row : rows) r.rows.push_back(row_of(row.cast<py::dict>()));
  tune::write_result(path, r);
}

}  // namespace

void bind_tune(py::module_& m) {
  m.def("tune_times", &tune::sample_times, py::arg("duration"), py::arg("samples"));
  m.def("tune_settings", &tune_settings, py::arg("scene"), py::arg("threads"));
  m.def("tune_run", &tune_run, py::arg("scene"), py::arg("setting"), py::arg("times"),
        py::arg("threads"), py::arg("wall_limit"));
  m.def("tune_row", &tune_row, py::arg("setting"), py::arg("run"), py::arg("reference"),
        py::arg("times"));
  m.def(
      "tune_distance",
      [](const py::array_t<double>& a, const py::array_t<double>& b) {
        const tune::SampledRun ra = run_of(a, {}), rb = run_of(b, {});
        std::vector<std::pair<double, double>> out;
        for (std::size_t k = 0; k < ra.at.size(); ++k) {
          const tune::Distance d = tune::distance(ra.at[k], rb.at[k]);
          out.emplace_back(d.rms, d.max);
        }
        return out;
      },
      py::arg("a"), py::arg("b"));
  m.def("tune_pick", &pick, py::arg("rows"), py::arg("tolerance"));
  m.def("tune_write_result", &write_result, py::arg("path"), py::arg("times"), py::arg("reference"),
        py::arg("self_error"), py::arg("reference_cost"), py::arg("stop_after"), py::arg("rows"));
}

}  // namespace clothlab::py_bindings
