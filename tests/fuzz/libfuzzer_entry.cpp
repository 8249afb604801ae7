// libFuzzer's entry point for one fuzz target, chosen at compile time by CLOTHLAB_FUZZ_TARGET
// (fuzz_scene, fuzz_obj or fuzz_wav); scripts/fuzz builds one binary per target with clang
// -fsanitize=fuzzer,address,undefined. The scene directory and a scratch directory come from
// the environment (CLOTHLAB_FUZZ_SCENES, CLOTHLAB_FUZZ_SCRATCH), set by scripts/fuzz.
#include <cstdlib>
#include <filesystem>

#include "tests/fuzz/fuzz_targets.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* scenes = std::getenv("CLOTHLAB_FUZZ_SCENES");
  const char* scratch = std::getenv("CLOTHLAB_FUZZ_SCRATCH");
  const std::string dir = scratch ? scratch : "/tmp/clothlab_fuzz";
  std::filesystem::create_directories(dir);
  clothlab::fuzz::set_context({scenes ? scenes : "scenes", dir});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return clothlab::fuzz::CLOTHLAB_FUZZ_TARGET(data, size);
}
