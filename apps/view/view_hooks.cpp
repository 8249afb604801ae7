// ViewHooks::from_environment: the test hooks of the window (view_app.hpp lists them), read from
// the environment once at start-up.
#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "apps/view/view_app.hpp"

namespace clothlab::vis {
namespace {

constexpr long kDefaultHookFrames = 60;  // frames a screenshot hook runs without EXIT_AFTER

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, ',')) parts.push_back(part);
  return parts;
}

}  // namespace

ViewHooks ViewHooks::from_environment() {
  ViewHooks hooks;
  if (const char* n = std::getenv("CLOTHLAB_VIEW_EXIT_AFTER_FRAMES"))
    hooks.exit_after_frames = std::max(0L, std::atol(n));
  if (const char* path = std::getenv("CLOTHLAB_VIEW_SCREENSHOT")) {
    hooks.screenshot = path;
    if (hooks.exit_after_frames == 0) hooks.exit_after_frames = kDefaultHookFrames;
  }
  if (const char* keys = std::getenv("CLOTHLAB_VIEW_KEYS")) hooks.keys = split_commas(keys);
  if (const char* cursor = std::getenv("CLOTHLAB_VIEW_CURSOR")) {
    const std::vector<std::string> xy = split_commas(cursor);
    if (xy.size() == 2) hooks.cursor = {std::atof(xy[0].c_str()), std::atof(xy[1].c_str())};
  }
  if (const char* n = std::getenv("CLOTHLAB_VIEW_CLICK")) hooks.click_frame = std::atol(n);
  if (const char* path = std::getenv("CLOTHLAB_VIEW_RECORD")) hooks.record = path;
  if (const char* open = std::getenv("CLOTHLAB_VIEW_OPEN")) {
    const std::string text(open);
    const auto colon = text.find(':');
    if (colon != std::string::npos) {
      hooks.open_frame = std::atol(text.substr(0, colon).c_str());
      hooks.open_scene = text.substr(colon + 1);
    }
  }
  if (const char* off = std::getenv("CLOTHLAB_VIEW_NO_AUDIO"))
    hooks.no_audio = std::string(off) == "1";
  if (const char* drag = std::getenv("CLOTHLAB_VIEW_DRAG")) {
    const std::vector<std::string> v = split_commas(drag);
    if (v.size() == 6) {
      std::array<double, 6> d{};
      for (std::size_t k = 0; k < 6; ++k) d[k] = std::atof(v[k].c_str());
      hooks.drag = d;
    }
  }
  return hooks;
}

}  // namespace clothlab::vis
