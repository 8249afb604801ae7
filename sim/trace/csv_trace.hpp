// CSV traces (docs/design.md, "CSV trace"). One header row, then per written step one row per
// traced vertex: step,time,[cloth,]vertex_i,vertex_j, then px,py,pz / vx,vy,vz / fx,fy,fz for the
// requested fields, then kinetic,elastic,gravity,total when "energy" is requested (the step's
// energy, repeated on each vertex row of that step). With energy but no traced vertex, each step
// has one row with vertex -1,-1 and no per-vertex columns. The cloth column appears only for
// [[cloth]] scenes. SI units; %.9g for float solvers, %.17g for double ones (round-trip exact).
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/temp_files.hpp"
#include "sim/solver.hpp"

namespace clothlab {

std::vector<std::string> trace_columns(const TraceSpec& spec, bool multi_cloth);

// Writes a trace to `path` atomically: rows go to a temporary file beside it, which commit()
// renames over `path`. A writer destroyed without commit() removes the temporary file, so the
// trace is complete or absent.
class TraceWriter {
 public:
  TraceWriter(const std::string& path, const TraceSpec& spec, bool multi_cloth, bool double_digits);
  ~TraceWriter();
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;

  // Writes the rows of the solver's current step. Updates the force field if forces are traced.
  void write_step(Solver& solver);
  void commit();
  // Whether every number written so far was finite, and the first column that was not
  // ("fx is not finite"); run_trace stops before committing such a file.
  bool finite() const { return bad_column_ < 0; }
  std::string first_non_finite() const;
  // The energy the last write_step() wrote, when the trace has energy columns.
  const std::optional<Energy>& last_energy() const { return last_energy_; }

 private:
  void number(double value);

  std::string path_, temp_path_;
  TempFileGuard temp_guard_{temp_path_};  // removed on SIGINT / SIGTERM too
  TraceSpec spec_;
  bool multi_cloth_;
  const char* format_;
  std::FILE* file_ = nullptr;
  std::vector<int> vertex_index_;
  int column_ = 0;       // the column number() writes next
  int bad_column_ = -1;  // the first non-finite column, or -1
  std::optional<Energy> last_energy_;
};

// A trace read back: column names and rows of numbers.
struct TraceTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const;  // -1 if absent
};
TraceTable read_trace_csv(const std::string& path);

}  // namespace clothlab
