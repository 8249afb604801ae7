// What every `clothlab bench` suite shares: a table that is printed for people (aligned columns,
// units in the headers) and written as CSV for notebooks (raw values, %.9g), the machine's
// foreign load, and a wall clock.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>
#include <vector>

namespace clothlab::bench {

struct Table {
  std::string name;  // file suffix of a summary table: <out stem>_<name>.csv
  std::string title;
  std::string note;  // a line under the title (what --quick leaves out); empty for none
  std::vector<std::string> columns;  // with units, e.g. "dt (s)"
  std::vector<std::vector<std::string>> rows;
  void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
};

// Aligned, with a title line and a rule under the header. Numbers are printed to 4 significant
// digits (the CSV keeps the cell as it is, %.9g), so that a table fits a terminal.
void print_table(std::ostream& out, const Table& table);

// A number cell as people read it: a fraction or exponent with more than 4 significant digits
// to %.4g ("0.0166666667" -> "0.01667"); integers and text as they are.
std::string for_people(const std::string& cell);

// "--quick leaves out: <what>" when quick, else empty (Table::note).
std::string quick_note(bool quick, const std::string& what);

// Writes `text` to `path` through a temporary file and a rename, so the file is complete or
// absent (its folder made if missing). Throws std::runtime_error on failure.
void write_text_file(const std::string& path, const std::string& text);
// Writes the table as CSV (one header row of the column names) through write_text_file().
void write_csv(const std::string& path, const Table& table);

std::string num(double value);                  // %.9g: the CSV form
std::string fixed(double value, int decimals);  // %.*f
std::string sci(double value, int digits = 3);  // %.*e with `digits` significant digits
std::string pct(double ratio);                  // 0.123 -> "12.3 %"

// One-minute load average of the machine (/proc/loadavg), NaN if unreadable: benchmarks print it
// so a reader can tell a noisy measurement (docs/design.md, "Performance notes").
double load_average();

// Wall-clock seconds since construction.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// The median of a few repetitions: robust against one run disturbed by another process.
double median(std::vector<double> values);

// The largest mean of `window` consecutive values, of all of them when there are fewer (0 for
// none): the slowest stretch of a run's frame times.
double slowest_window_mean(const std::vector<double>& values, std::size_t window);

}  // namespace clothlab::bench
