// The clothlab subcommands. Each returns the process exit status: 0 success, 2 bad input
// (message names file, line and key, or the argument), 1 runtime failure (e.g. divergence).
#pragma once

#include <string>
#include <vector>

namespace clothlab::app {

struct CheckArgs {
  std::string scene;
  std::vector<std::string> overrides;
};

struct TraceArgs {
  std::string scene;
  std::vector<std::string> overrides;
  double duration = 0.0;
  std::string out;
};

int run_check(const CheckArgs& args);
int run_trace_command(const TraceArgs& args);

// The command line that replays a run, printed with runtime failures (pbrt's habit).
std::string replay_command(const std::string& scene, const std::vector<std::string>& overrides,
                           double duration);

}  // namespace clothlab::app
