// The memory a built scene will need against what this machine can give it, checked before the
// solver is built (issue 21: a 4000 x 4000 cloth needs about 19 GB).
#pragma once

#include <cstdint>
#include <string>

#include "sim/scene/scene.hpp"

namespace clothlab::app {

// Bytes this process may still allocate: the least of /proc/meminfo's MemAvailable, the cgroup
// v2 limit less its current use, and RLIMIT_AS (each where the machine has it).
std::uint64_t available_bytes();

// Throws SceneError, at the largest cloth's resolution with both figures, when the scene will not
// fit in `available` bytes.
void check_memory(const Scene& scene, std::uint64_t available);

}  // namespace clothlab::app
