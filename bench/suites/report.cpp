#include "bench/suites/report.hpp"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace clothlab::bench {

namespace {

std::string format(const char* pattern, double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, digits, value);
  return buffer;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::string for_people(const std::string& cell) {
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (cell.empty() || *end != '\0' || cell.find_first_of(".eE") == std::string::npos) return cell;
  int digits = 0;  // significant digits of the mantissa
  bool leading = true;
  for (char ch : cell) {
    if (ch == 'e' || ch == 'E') break;
    if (ch < '0' || ch > '9') continue;
    leading = leading && ch == '0';
    digits += leading ? 0 : 1;
  }
  return digits > 4 ? format("%.*g", value, 4) : cell;
}

std::string quick_note(bool quick, const std::string& what) {
  return quick ? "--quick leaves out: " + what : std::string();
}

void print_table(std::ostream& out, const Table& table) {
  std::vector<std::vector<std::string>> rows;
  rows.reserve(table.rows.size());
  for (const auto& row : table.rows) {
    rows.emplace_back();
    for (const std::string& cell : row) rows.back().push_back(for_people(cell));
  }
  std::vector<std::size_t> width(table.columns.size(), 0);
  for (std::size_t c = 0; c < table.columns.size(); ++c) width[c] = table.columns[c].size();
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size() && c < width.size(); ++c)
      width[c] = std::max(width[c], row[c].size());
  // Numbers align right, text left; a column is text when its first cell does not parse.
  std::vector<bool> numeric(width.size(), true);
  if (!rows.empty())
    for (std::size_t c = 0; c < width.size() && c < rows[0].size(); ++c) {
      const std::string& cell = rows[0][c];
      char* end = nullptr;
      std::strtod(cell.c_str(), &end);
      numeric[c] = !cell.empty() && end != cell.c_str();
    }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t c = 0; c < width.size(); ++c) {
      const std::string& cell = c < cells.size() ? cells[c] : std::string();
      const std::string pad(width[c] - cell.size(), ' ');
      text += (c ? "  " : "") + (numeric[c] ? pad + cell : cell + pad);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out << text << '\n';
  };
  out << '\n' << table.title << '\n';
  if (!table.note.empty()) out << table.note << '\n';
  line(table.columns);
  std::size_t total = 0;
  for (std::size_t w : width) total += w + 2;
  out << std::string(total > 2 ? total - 2 : 0, '-') << '\n';
  for (const auto& row : rows) line(row);
  out.flush();
}

void write_text_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const fs::path temporary = target.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream f(temporary);
    if (!f) throw std::runtime_error("cannot write " + temporary.string());
    f << text;
    f.flush();
    if (!f) {
      fs::remove(temporary);
      throw std::runtime_error("error while writing " + temporary.string());
    }
  }
  fs::rename(temporary, target);
}

void write_csv(const std::string& path, const Table& table) {
  std::ostringstream text;
  auto write_row = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) text << (c ? "," : "") << csv_field(cells[c]);
    text << '\n';
  };
  write_row(table.columns);
  for (const auto& row : table.rows) write_row(row);
  write_text_file(path, text.str());
}

std::string num(double value) {
  if (std::isnan(value)) return "nan";
  return format("%.*g", value, 9);
}

std::string fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  return format("%.*f", value, decimals);
}

std::string sci(double value, int digits) {
  if (std::isnan(value)) return "-";
  return format("%.*e", value, digits - 1);
}

std::string pct(double ratio) {
  if (std::isnan(ratio)) return "-";
  return format("%.*f", 100.0 * ratio, 1) + " %";
}

double load_average() {
  std::ifstream f("/proc/loadavg");
  double one_minute = NAN;
  if (!(f >> one_minute)) return NAN;
  return one_minute;
}

double median(std::vector<double> values) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double slowest_window_mean(const std::vector<double>& values, std::size_t window) {
  const std::size_t w = std::min(window, values.size());
  if (w == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < w; ++k) sum += values[k];
  double most = sum;
  for (std::size_t k = w; k < values.size(); ++k) {
    sum += values[k] - values[k - w];
    most = std::max(most, sum);
  }
  return most / double(w);
}

}  // namespace clothlab::bench
