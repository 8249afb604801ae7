// clothlab: the command-line entry point. Only wires the command line to the subcommands.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "apps/clothlab/commands.hpp"

namespace {

void add_scene_options(CLI::App& cmd, std::string& scene, std::vector<std::string>& overrides) {
  cmd.add_option("scene", scene, "scene file (TOML)")->required();
  cmd.add_option("--set", overrides, "override a scene value, key.path=value (repeatable)")
      ->take_last()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace clothlab::app;
  CLI::App app{"ClothLab: a laboratory for simulating cloth and looking at it scientifically."};
  app.require_subcommand(1);

  CheckArgs check;
  auto* check_cmd = app.add_subcommand("check", "parse and validate a scene, then exit");
  add_scene_options(*check_cmd, check.scene, check.overrides);

  TraceArgs trace;
  auto* trace_cmd = app.add_subcommand("trace", "run a scene headless and write a CSV trace");
  add_scene_options(*trace_cmd, trace.scene, trace.overrides);
  trace_cmd->add_option("--duration", trace.duration, "simulated seconds to run")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            const double d = std::strtod(s.c_str(), nullptr);
            return std::isfinite(d) && d > 0.0 && d <= 1e6
                       ? std::string()
                       : std::string("must be a finite number in (0, 1e6] seconds");
          },
          "SECONDS"));
  trace_cmd->add_option("--out", trace.out, "CSV file to write")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help or the error
    return rc == 0 ? 0 : 2;
  }
  if (*check_cmd) return run_check(check);
  if (*trace_cmd) return run_trace_command(trace);
  return 2;
}
