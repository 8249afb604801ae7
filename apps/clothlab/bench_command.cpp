// `clothlab bench`: runs one suite (or all), prints its tables and writes them as CSV.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/clothlab/commands.hpp"
#include "bench/suites/run_record.hpp"
#include "bench/suites/suites.hpp"
#include "sim/core/passive_openmp.hpp"

namespace clothlab::app {

namespace {

std::vector<bench::Table> run_suite(const std::string& name, const bench::SuiteOptions& o) {
  if (name == "accuracy") return bench::accuracy_suite(o);
  if (name == "largestep") return bench::large_step_suite(o);
  if (name == "stability") return bench::stability_suite(o);
  if (name == "scaling") return bench::scaling_suite(o);
  if (name == "views") return bench::views_suite(o);
  if (name == "rendering") return bench::rendering_suite(o);
  if (name == "backends") return bench::backends_suite(o);
  if (name == "contact") return bench::contact_suite(o);
  if (name == "realtime") return bench::realtime_suite(o);
  return bench::features_suite(o);
}

// The first table goes to `path`; a summary table named "x" to <stem>_x.csv beside it. Each
// file's name and its table's title go into `record`.
void write_tables(const std::filesystem::path& path, const std::vector<bench::Table>& tables,
                  bench::RunRecord& record) {
  for (std::size_t t = 0; t < tables.size(); ++t) {
    std::filesystem::path file = path;
    if (t > 0)
      file = path.parent_path() /
             (path.stem().string() + "_" + tables[t].name + path.extension().string());
    bench::write_csv(file.string(), tables[t]);
    record.tables.push_back({file.filename().string(), tables[t].title, tables[t].note});
    std::cout << "wrote " << file.string() << '\n';
  }
}

}  // namespace

int run_bench(const BenchArgs& args) {
  namespace fs = std::filesystem;
  std::vector<std::string> suites;
  if (args.suite == "all")
    suites.assign(std::begin(bench::kSuiteNames), std::end(bench::kSuiteNames));
  else
    suites.push_back(args.suite);
  bench::SuiteOptions options;
  options.quick = args.quick;
  options.threads = args.threads;
  options.log = args.verbose ? &std::cerr : nullptr;
  std::cout << "clothlab bench: one-minute load average before the run "
            << bench::fixed(bench::load_average(), 2)
            << " (the machine's other work; timings are only comparable within one run); OpenMP "
            << openmp_wait_policy() << "\n";
  try {
    for (const std::string& suite : suites) {
      // One suite: --out is its CSV file. All suites: --out is a directory.
      fs::path out =
          args.out.empty() ? fs::path("out/bench") / (suite + ".csv") : fs::path(args.out);
      // An existing directory takes the suite's file whatever the number of suites.
      if (!args.out.empty() && (suites.size() > 1 || fs::is_directory(args.out)))
        out = fs::path(args.out) / (suite + ".csv");
      bench::RunRecord record;
      record.suite = suite;
      record.date = bench::utc_now();
      record.machine = bench::machine_description();
      record.quick = args.quick;
      record.threads = args.threads;
      record.load_before = bench::load_average();
      const bench::Stopwatch clock;
      const std::vector<bench::Table> tables = run_suite(suite, options);
      // The summary first (the answer), then the tables it was drawn from.
      for (const bench::Table& t : tables)
        if (t.name == "summary") bench::print_table(std::cout, t);
      for (const bench::Table& t : tables)
        if (t.name != "summary") bench::print_table(std::cout, t);
      std::cout << '\n';
      write_tables(out, tables, record);
      record.seconds = clock.seconds();
      record.load_after = bench::load_average();
      // The run's record beside its tables: scripts/results reads it (docs/results.md).
      fs::path json = out;
      bench::write_run_record(json.replace_extension(".json").string(), record);
      std::cout << suite << ": " << bench::fixed(record.seconds, 1) << " s, load average now "
                << bench::fixed(record.load_after, 2) << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "clothlab bench: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace clothlab::app
