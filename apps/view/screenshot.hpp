// F12: the window's default framebuffer as a PNG.
#pragma once

#include <string>

#include "vis/textures/image.hpp"

namespace clothlab::vis {

// Reads the back buffer of the default framebuffer (call after drawing, before swapping), rows
// flipped to top-first, alpha made opaque (the UI's blending leaves it below 1).
Image read_default_framebuffer(int width, int height);

// "clothlab_screenshot_<YYYYmmdd_HHMMSS_mmm>.png": local time, with milliseconds so two quick
// presses do not overwrite each other.
std::string screenshot_file_name();
// "clothlab_record_<YYYYmmdd_HHMMSS_mmm>.csv", likewise: the panel's Record.
std::string record_file_name();

}  // namespace clothlab::vis
