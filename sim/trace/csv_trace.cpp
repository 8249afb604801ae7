#include "sim/trace/csv_trace.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace clothlab {

std::vector<std::string> trace_columns(const TraceSpec& spec, bool multi_cloth) {
  std::vector<std::string> cols = {"step", "time"};
  if (multi_cloth) cols.push_back("cloth");
  cols.insert(cols.end(), {"vertex_i", "vertex_j"});
  if (!spec.vertices.empty()) {
    if (spec.position) cols.insert(cols.end(), {"px", "py", "pz"});
    if (spec.velocity) cols.insert(cols.end(), {"vx", "vy", "vz"});
    if (spec.force) cols.insert(cols.end(), {"fx", "fy", "fz"});
  }
  if (spec.energy) cols.insert(cols.end(), {"kinetic", "elastic", "gravity", "total"});
  return cols;
}

TraceWriter::TraceWriter(const std::string& path, const TraceSpec& spec, bool multi_cloth,
                         bool double_digits)
    : path_(path),
      temp_path_(path + ".tmp." + std::to_string(::getpid())),
      spec_(spec),
      multi_cloth_(multi_cloth),
      format_(double_digits ? "%.17g" : "%.9g") {
  file_ = std::fopen(temp_path_.c_str(), "w");
  if (!file_)
    throw std::runtime_error("cannot write trace file '" + path + "': " + std::strerror(errno));
  const auto cols = trace_columns(spec_, multi_cloth_);
  for (std::size_t c = 0; c < cols.size(); ++c) {
    std::fputs(cols[c].c_str(), file_);
    std::fputc(c + 1 < cols.size() ? ',' : '\n', file_);
  }
}

TraceWriter::~TraceWriter() {
  if (file_) {
    std::fclose(file_);
    std::remove(temp_path_.c_str());
  }
}

void TraceWriter::number(double value) {
  if (!std::isfinite(value) && bad_column_ < 0) bad_column_ = column_;
  ++column_;
  std::fputc(',', file_);
  std::fprintf(file_, format_, value);
}

void TraceWriter::write_step(Solver& solver) {
  if (vertex_index_.empty())
    for (const auto& v : spec_.vertices)
      vertex_index_.push_back(solver.vertex_index({v.cloth, v.i, v.j}));
  if (spec_.force && !spec_.vertices.empty()) solver.update_force_field();
  const Energy e = spec_.energy ? solver.energy() : Energy{};
  last_energy_.reset();
  if (spec_.energy) last_energy_ = e;
  auto row_start = [&](const TraceVertex& v) {
    column_ = 1;  // the next number() is column 1, time
    std::fprintf(file_, "%ld", solver.step_count());
    number(solver.time());
    if (multi_cloth_) std::fprintf(file_, ",%d", v.cloth);
    std::fprintf(file_, ",%d,%d", v.i, v.j);
    column_ += multi_cloth_ ? 3 : 2;
  };
  auto energy_cols = [&] {
    if (!spec_.energy) return;
    for (double value : {e.kinetic, e.elastic, e.gravity, e.total()}) number(value);
  };
  if (spec_.vertices.empty()) {
    row_start({-1, -1, -1});
    energy_cols();
    std::fputc('\n', file_);
    return;
  }
  for (std::size_t k = 0; k < spec_.vertices.size(); ++k) {
    row_start(spec_.vertices[k]);
    const int idx = vertex_index_[k];
    auto vec = [&](const Vec3d& a) { number(a[0]), number(a[1]), number(a[2]); };
    if (spec_.position) vec(solver.position(idx));
    if (spec_.velocity) vec(solver.velocity(idx));
    if (spec_.force) vec(solver.force(idx));
    energy_cols();
    std::fputc('\n', file_);
  }
}

std::string TraceWriter::first_non_finite() const {
  if (bad_column_ < 0) return "";
  const auto cols = trace_columns(spec_, multi_cloth_);
  return cols[std::size_t(bad_column_)] + " is not finite";
}

void TraceWriter::commit() {
  errno = 0;
  const bool write_ok = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool close_ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!write_ok || !close_ok || std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int why = errno;  // ENOSPC on a full disk: the reason the user can act on
    std::remove(temp_path_.c_str());
    throw std::runtime_error("cannot write trace file '" + path_ + "'" +
                             (why ? std::string(": ") + std::strerror(why) : std::string()));
  }
}

int TraceTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return static_cast<int>(c);
  return -1;
}

TraceTable read_trace_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read trace file '" + path + "'");
  TraceTable t;
  std::string line, cell;
  if (!std::getline(in, line)) throw std::runtime_error("'" + path + "': empty trace file");
  std::istringstream header(line);
  while (std::getline(header, cell, ',')) t.columns.push_back(cell);
  for (int row = 2; std::getline(in, line); ++row) {
    std::vector<double> values;
    std::istringstream cells(line);
    while (std::getline(cells, cell, ',')) {
      char* end = nullptr;
      values.push_back(std::strtod(cell.c_str(), &end));
      if (end == cell.c_str() || *end != '\0')
        throw std::runtime_error("'" + path + "' line " + std::to_string(row) + ": bad number '" +
                                 cell + "'");
    }
    if (values.size() != t.columns.size())
      throw std::runtime_error("'" + path + "' line " + std::to_string(row) +
                               ": wrong column count");
    t.rows.push_back(std::move(values));
  }
  return t;
}

}  // namespace clothlab
