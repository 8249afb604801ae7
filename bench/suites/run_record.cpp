#include "bench/suites/run_record.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include "bench/suites/report.hpp"
#include "sim/core/quoted_string.hpp"

namespace clothlab::bench {
namespace {

// A JSON number, or null for NaN (an unreadable load average).
std::string json_number(double value) {
  return std::isfinite(value) ? num(value) : "null";
}

std::string to_json(const RunRecord& r) {
  std::ostringstream j;
  j << "{\n  \"suite\": " << quoted_string(r.suite) << ",\n  \"date\": " << quoted_string(r.date)
    << ",\n  \"machine\": " << quoted_string(r.machine)
    << ",\n  \"quick\": " << (r.quick ? "true" : "false") << ",\n  \"threads\": " << r.threads
    << ",\n  \"load_before\": " << json_number(r.load_before)
    << ",\n  \"load_after\": " << json_number(r.load_after)
    << ",\n  \"seconds\": " << json_number(r.seconds) << ",\n  \"tables\": [";
  for (std::size_t t = 0; t < r.tables.size(); ++t)
    j << (t ? "," : "") << "\n    {\"file\": " << quoted_string(r.tables[t].file)
      << ", \"title\": " << quoted_string(r.tables[t].title)
      << ", \"note\": " << quoted_string(r.tables[t].note) << "}";
  j << "\n  ]\n}\n";
  return j.str();
}

}  // namespace

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string machine_description() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos) model = line.substr(line.find_first_not_of(" \t", colon + 1));
    break;
  }
  return model + " (" + std::to_string(std::thread::hardware_concurrency()) + " cores)";
}

void write_run_record(const std::string& path, const RunRecord& record) {
  write_text_file(path, to_json(record));
}

}  // namespace clothlab::bench
