#include "apps/clothlab/remote_tune.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tune/result_file.hpp"

extern char** environ;

namespace clothlab::app {
namespace {

std::string python() {
  const char* chosen = std::getenv("CLOTHLAB_PYTHON");
  return chosen && *chosen ? chosen : "/usr/bin/python3";
}

std::vector<std::string> command(const TuneArgs& args, const std::string& out) {
  char duration[32];
  std::snprintf(duration, sizeof duration, "%.17g", args.duration);
  std::vector<std::string> c = {python(),   "-m",          "clothlab.remote_tune",
                                args.scene, "--scheduler", args.scheduler,
                                "--out",    out,           "--duration",
                                duration,   "--threads",   std::to_string(args.threads)};
  for (const std::string& o : args.overrides) c.insert(c.end(), {"--set", o});
  if (args.quiet) c.push_back("--quiet");
  return c;
}

// Runs `argv` with the module's folder first on PYTHONPATH; its exit status, or -1 when it
// could not be started.
int run(const std::vector<std::string>& argv) {
  const char* path = std::getenv("PYTHONPATH");
  std::string module_path = CLOTHLAB_PYTHON_DIR;
  if (path && *path) module_path.append(":").append(path);
  setenv("PYTHONPATH", module_path.c_str(), 1);
  std::vector<char*> raw;
  for (const std::string& a : argv) raw.push_back(const_cast<char*>(a.c_str()));
  raw.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, raw[0], nullptr, nullptr, raw.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

}  // namespace

RemoteTune tune_on_scheduler(const TuneArgs& args) {
  RemoteTune r;
  if (std::string(CLOTHLAB_PYTHON_DIR).empty()) {
    std::fprintf(stderr,
                 "clothlab tune: --scheduler: this build has no Python module (configured with "
                 "CLOTHLAB_PYTHON=OFF)\n");
    r.status = 2;
    return r;
  }
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("clothlab-tune-" + std::to_string(::getpid()) + ".toml");
  const std::vector<std::string> argv = command(args, out.string());
  const int status = run(argv);
  if (status == -1) {
    std::fprintf(stderr, "clothlab tune: --scheduler: cannot run %s\n", argv[0].c_str());
    r.status = 1;
  } else if (status != 0) {
    r.status = status == 2 ? 2 : 1;  // the Python side said why
  } else {
    try {
      r.result = tune::read_result(out.string());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "clothlab tune: %s\n", e.what());
      r.status = 1;
    }
  }
  std::error_code ec;
  std::filesystem::remove(out, ec);
  return r;
}

}  // namespace clothlab::app
