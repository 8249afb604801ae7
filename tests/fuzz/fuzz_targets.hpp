// Fuzz targets (issue 21): one input of each kind through the code that reads it, and the
// properties every input must keep whatever it holds. An input ClothLab refuses (SceneError,
// ObjError, AudioError) is a pass; a crash, a sanitizer report, any other exception, or a
// non-finite value where a finite one is promised is a finding: the target prints it and
// aborts. The same targets run under libFuzzer (scripts/fuzz, clang) and under the
// deterministic mutation driver (mutation_driver.cpp) that ctest runs for a bounded time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace clothlab::fuzz {

// Where the targets find the scenes' relative files (assets, meshes) and write their scratch
// files; set once by the driver before the first input.
struct FuzzContext {
  std::string scene_dir;    // a scene's relative paths resolve here (the repo's scenes/)
  std::string scratch_dir;  // OBJ and sound inputs are written here to be read back
  std::string program;      // the clothlab executable (the output-path target runs it)
};
void set_context(const FuzzContext& context);
const FuzzContext& context();

// Scene text: parse, validate, load, build a solver (small scenes only), take a few steps and
// write a trace; positions, velocities and every written number stay finite unless the run
// reports a divergence.
int fuzz_scene(const std::uint8_t* data, std::size_t size);
// OBJ text: read as a mesh collider's and a mesh cloth's file; a mesh that is read has finite
// coordinates, triangles inside its vertex list, and a mesh cloth built from it steps finitely.
int fuzz_obj(const std::uint8_t* data, std::size_t size);
// A sound file: read and analysed as [music], danced to; every sample, beat and pose is finite.
int fuzz_wav(const std::uint8_t* data, std::size_t size);
// Bytes choosing a command, an output option and a path among prepared files, links, devices,
// pipes and sockets (fuzz_output_paths.cpp): `clothlab` exits 0, 1 or 2 in time, and changes
// nothing but the output it wrote; never under libFuzzer (it starts a process per input).
int fuzz_output_paths(const std::uint8_t* data, std::size_t size);

// A property that did not hold: prints "fuzz finding: what" and aborts.
[[noreturn]] void finding(const std::string& what);

}  // namespace clothlab::fuzz
