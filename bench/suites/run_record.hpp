// What one `clothlab bench` suite run was: where, when, under what load, and which tables it
// wrote with their titles. Written beside the suite's CSV files as <stem>.json, so that
// scripts/results can put the tables into docs/results.md with the machine and date they were
// measured on (docs/results.md says how).
#pragma once

#include <string>
#include <vector>

namespace clothlab::bench {

struct TableRecord {
  std::string file;  // the CSV file's name, beside the record
  std::string title, note;
};

struct RunRecord {
  std::string suite;
  std::string date;     // UTC, ISO 8601, when the suite started
  std::string machine;  // CPU model and core count (/proc/cpuinfo)
  bool quick = false;
  int threads = 1;
  double load_before = 0.0, load_after = 0.0;  // one-minute load average
  double seconds = 0.0;                        // the suite's wall time
  std::vector<TableRecord> tables;
};

// "2026-12-04T11:58:03Z".
std::string utc_now();
// "AMD EPYC 9B14 (2 cores)": the first CPU model name in /proc/cpuinfo and the cores online.
std::string machine_description();

// Writes `record` as JSON to `path` through a temporary file and a rename (complete or absent).
// Throws std::runtime_error on failure.
void write_run_record(const std::string& path, const RunRecord& record);

}  // namespace clothlab::bench
