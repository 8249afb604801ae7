// Frames into an MP4 through Debian's ffmpeg (H.264, yuv420p): raw RGBA frames go down a pipe.
// The video is written to a temporary file and renamed when ffmpeg succeeds: complete or absent.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace clothlab::app {

class VideoPipe {
 public:
  // Throws std::runtime_error when ffmpeg cannot be started.
  VideoPipe(const std::string& path, int width, int height, double fps);
  ~VideoPipe();
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  void write(const std::vector<std::uint8_t>& rgba);
  // Closes the pipe; throws if ffmpeg failed. Renames the temporary file into place.
  void finish();

 private:
  std::string path_, temp_;
  std::FILE* pipe_ = nullptr;
  std::size_t frame_bytes_;
};

}  // namespace clothlab::app
