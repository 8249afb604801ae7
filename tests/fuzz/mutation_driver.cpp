// clothlab_fuzz: the deterministic mutation driver over the fuzz targets (fuzz_targets.hpp).
//   clothlab_fuzz --target scene|obj|wav|outputs --seconds S [--seed N] [--scenes DIR]
//                 [--scratch DIR] [--program CLOTHLAB] SEED_FILE_OR_DIR...
// Each round takes a seed, mutates it (mutations.hpp) and runs the target on it; every seed is
// also run once as it is. The input under test is written to SCRATCH/current.<target> first, so
// a run that dies (a finding, a sanitizer report, a hang past kHangSeconds) leaves the input
// that did it. Prints the rounds and rounds per second; exit 0 when nothing was found.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/mutations.hpp"

namespace fs = std::filesystem;
using namespace clothlab::fuzz;

namespace {

// One input may take this long (a valid scene's build and four steps take milliseconds).
constexpr unsigned kHangSeconds = 20;

struct Target {
  const char* name;
  int (*run)(const std::uint8_t*, std::size_t);
  InputKind kind;
  std::vector<std::string> extensions;
};

const Target kTargets[] = {
    {"scene", fuzz_scene, InputKind::text, {".toml"}},
    {"obj", fuzz_obj, InputKind::text, {".obj"}},
    {"wav", fuzz_wav, InputKind::binary, {".wav", ".mp3", ".flac", ".ogg"}},
    {"outputs", fuzz_output_paths, InputKind::binary, {".outputs"}},
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> seeds_of(const std::vector<std::string>& paths, const Target& t) {
  std::vector<fs::path> files;
  for (const std::string& p : paths) {
    if (fs::is_directory(p)) {
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.emplace_back(p);
    }
  }
  std::sort(files.begin(), files.end());  // a fixed order, so a seed gives the same run
  std::vector<std::string> seeds;
  for (const fs::path& f : files)
    for (const std::string& ext : t.extensions)
      if (f.extension() == ext) seeds.push_back(read_file(f));
  return seeds;
}

// The SIGALRM message needs a fixed buffer: a handler may only call async-signal-safe write().
char g_hang_message[512];

extern "C" void on_hang(int) {
  ssize_t ignored = ::write(2, g_hang_message, std::strlen(g_hang_message));
  (void)ignored;
  ::_exit(1);
}

struct Options {
  const Target* target = nullptr;
  double seconds = 10.0;
  std::uint64_t seed = 1;
  std::string scenes = ".", scratch = ".", program = "clothlab";
  std::vector<std::string> corpus;
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--target" && has_value) {
      const std::string name = argv[++i];
      for (const Target& t : kTargets)
        if (name == t.name) o.target = &t;
    } else if (a == "--seconds" && has_value) {
      o.seconds = std::atof(argv[++i]);
    } else if (a == "--seed" && has_value) {
      o.seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (a == "--scenes" && has_value) {
      o.scenes = argv[++i];
    } else if (a == "--scratch" && has_value) {
      o.scratch = argv[++i];
    } else if (a == "--program" && has_value) {
      o.program = argv[++i];
    } else {
      o.corpus.push_back(a);
    }
  }
  return o.target && !o.corpus.empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: clothlab_fuzz --target scene|obj|wav|outputs --seconds S [--seed N] "
                 "[--scenes DIR] [--scratch DIR] [--program CLOTHLAB] SEED_FILE_OR_DIR...\n");
    return 2;
  }
  fs::create_directories(o.scratch);
  set_context({fs::absolute(o.scenes).string(), fs::absolute(o.scratch).string(),
               fs::absolute(o.program).string()});
  const std::vector<std::string> seeds = seeds_of(o.corpus, *o.target);
  if (seeds.empty()) {
    std::fprintf(stderr, "clothlab_fuzz: no %s seeds in the corpus\n", o.target->name);
    return 2;
  }
  const std::string current = context().scratch_dir + "/current." + o.target->name;
  std::snprintf(g_hang_message, sizeof g_hang_message,
                "fuzz finding: an input ran longer than %u s (kept in %s)\n", kHangSeconds,
                current.c_str());
  std::signal(SIGALRM, on_hang);

  Random random(o.seed);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  long rounds = 0;
  for (; rounds < long(seeds.size()) || elapsed() < o.seconds; ++rounds) {
    const std::size_t k = std::size_t(rounds) % seeds.size();
    const std::string input =
        rounds < long(seeds.size())
            ? seeds[k]
            : mutate(seeds[random.below(seeds.size())], seeds, o.target->kind, random);
    std::ofstream(current, std::ios::binary) << input;
    ::alarm(kHangSeconds);
    try {
      o.target->run(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz finding: uncaught %s (kept in %s)\n", e.what(), current.c_str());
      return 1;
    }
    ::alarm(0);
  }
  fs::remove(current);
  const double t = elapsed();
  std::printf(
      "clothlab_fuzz %s: %ld inputs (%zu seeds) in %.1f s, %.0f per second, seed %llu, "
      "no findings\n",
      o.target->name, rounds, seeds.size(), t, double(rounds) / t,
      static_cast<unsigned long long>(o.seed));
  return 0;
}
