#include "apps/clothlab/memory_check.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "sim/model/build_estimate.hpp"
#include "sim/model/memory_estimate.hpp"
#include "sim/scene/validate.hpp"

namespace clothlab::app {
namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

// The first number in `path` (a cgroup file holds "max" when unlimited), or kUnlimited.
std::uint64_t number_in(const char* path) {
  std::ifstream in(path);
  std::uint64_t value = 0;
  return in >> value ? value : kUnlimited;
}

std::uint64_t mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return kUnlimited;
}

std::string gigabytes(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GB", double(bytes) / 1e9);
  return buf;
}

}  // namespace

std::uint64_t available_bytes() {
  std::uint64_t limit = mem_available();
  const std::uint64_t cgroup = number_in("/sys/fs/cgroup/memory.max");
  if (cgroup != kUnlimited) {
    const std::uint64_t used = number_in("/sys/fs/cgroup/memory.current");
    limit = std::min(limit, cgroup > used && used != kUnlimited ? cgroup - used : 0);
  }
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    limit = std::min<std::uint64_t>(limit, as.rlim_cur);
  return limit;
}

std::string build_needs(const Scene& scene) {
  const double s = estimated_build_seconds(scene);
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, s >= 10.0 ? "%.0f s" : "%.2g s", s);
  const auto vertices = static_cast<std::uint64_t>(scene_vertices(scene));
  return "about " + gigabytes(estimated_solver_bytes(scene)) + " and " + seconds + " to build (" +
         std::to_string(vertices) + " vertices, " + to_string(scene.solver.integrator) + ", " +
         (scene.solver.precision == Precision::f64 ? "double" : "float") + ")";
}

SceneError size_error(const Scene& scene, const std::string& message) {
  const ClothSpec& largest = *std::max_element(
      scene.cloths.begin(), scene.cloths.end(), [](const ClothSpec& a, const ClothSpec& b) {
        return std::int64_t{a.resolution[0]} * a.resolution[1] <
               std::int64_t{b.resolution[0]} * b.resolution[1];
      });
  const std::string key = largest.key + ".resolution";
  return SceneError(location_of(scene, key), key, message);
}

void check_memory(const Scene& scene, std::uint64_t available) {
  if (estimated_solver_bytes(scene) <= available) return;
  throw size_error(scene, "the scene needs " + build_needs(scene) + " and this machine can give " +
                              gigabytes(available) + "; lower the resolution");
}

}  // namespace clothlab::app
