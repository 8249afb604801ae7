#include "tune/result_file.hpp"

#include <cmath>
#include <stdexcept>

#include "tune/toml_io.hpp"

namespace clothlab::tune {
namespace {

std::vector<double> rms_of(const std::vector<Distance>& d) {
  std::vector<double> out;
  for (const Distance& e : d) out.push_back(e.rms);
  return out;
}

std::vector<double> max_of(const std::vector<Distance>& d) {
  std::vector<double> out;
  for (const Distance& e : d) out.push_back(e.max);
  return out;
}

std::vector<Distance> distances(const toml::table& t) {
  const std::vector<double> rms = toml_io::numbers(t["rms"]), max = toml_io::numbers(t["max"]);
  if (rms.size() != max.size()) throw std::runtime_error("rms and max differ in length");
  std::vector<Distance> out;
  for (std::size_t k = 0; k < rms.size(); ++k) out.push_back({rms[k], max[k]});
  return out;
}

const toml::table& table_at(const toml::node* n, const char* what) {
  if (!n || !n->as_table()) throw std::runtime_error(std::string("no ") + what);
  return *n->as_table();
}

}  // namespace

void write_result(const std::string& path, const Result& r) {
  toml_io::write_atomically(path, [&](std::ostream& out) {
    out << "# clothlab tune (docs/tuning.md): a whole tune's table\ntimes = "
        << toml_io::exact_list(r.times) << "\n\n[reference]\n";
    toml_io::write_setting(out, r.reference.setting);
    out << "rms = " << toml_io::exact_list(rms_of(r.reference.self))
        << "\nmax = " << toml_io::exact_list(max_of(r.reference.self))
        << "\ncost = " << toml_io::exact(r.reference.cost)
        << "\nstop_after = " << toml_io::exact(r.reference.stop_after) << "\n";
    for (const Row& row : r.rows) {
      out << "\n[[rows]]\n";
      toml_io::write_setting(out, row.setting);
      out << "rms = " << toml_io::exact_list(rms_of(row.error))
          << "\nmax = " << toml_io::exact_list(max_of(row.error))
          << "\nenergy_drift = " << toml_io::exact(row.energy_drift)
          << "\ncost = " << toml_io::exact(row.cost)
          << "\nstatus = " << toml::value<std::string>(row.status) << "\n";
    }
  });
}

Result read_result(const std::string& path) {
  try {
    const toml::table t = toml::parse_file(path);
    Result r;
    r.times = toml_io::numbers(t["times"]);
    const toml::table& ref = table_at(t.get("reference"), "[reference]");
    r.reference.setting = toml_io::setting_from(ref);
    r.reference.self = distances(ref);
    r.reference.cost = toml_io::number(ref["cost"]);
    r.reference.stop_after = toml_io::number(ref["stop_after"]);
    if (r.times.empty() || r.reference.self.size() != r.times.size())
      throw std::runtime_error("the reference's errors do not match the sample times");
    if (const toml::array* rows = t["rows"].as_array())
      for (const toml::node& n : *rows) {
        const toml::table& row = table_at(&n, "row");
        Row out;
        out.setting = toml_io::setting_from(row);
        out.error = distances(row);
        out.energy_drift = toml_io::number(row["energy_drift"]);
        out.cost = toml_io::number(row["cost"]);
        out.status = row["status"].value_or(std::string("unreadable"));
        r.rows.push_back(std::move(out));
      }
    return r;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a tune's result: " + e.what());
  }
}

}  // namespace clothlab::tune
