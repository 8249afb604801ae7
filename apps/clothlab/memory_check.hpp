// The memory a built scene will need against what this machine can give it, checked before the
// solver is built (issue 21: a 4000 x 4000 cloth needs about 19 GB).
#pragma once

#include <cstdint>
#include <string>

#include "sim/scene/scene.hpp"
#include "sim/scene/validate.hpp"

namespace clothlab::app {

// Bytes this process may still allocate: the least of /proc/meminfo's MemAvailable, the cgroup
// v2 limit less its current use, and RLIMIT_AS (each where the machine has it).
std::uint64_t available_bytes();

// "about 1.9 GB and 45 s to build (16000000 vertices, xpbd, float)": the estimates of
// sim/model/memory_estimate.hpp and sim/model/build_estimate.hpp.
std::string build_needs(const Scene& scene);

// A SceneError at the largest cloth's resolution (its file, line and key).
SceneError size_error(const Scene& scene, const std::string& message);

// Throws size_error, with both figures, when the scene will not fit in `available` bytes.
void check_memory(const Scene& scene, std::uint64_t available);

}  // namespace clothlab::app
