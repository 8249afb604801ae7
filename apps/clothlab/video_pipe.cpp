#include "apps/clothlab/video_pipe.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <stdexcept>

namespace clothlab::app {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

VideoPipe::VideoPipe(const std::string& path, int width, int height, double fps)
    : path_(path),
      temp_(path + ".tmp." + std::to_string(::getpid()) + ".mp4"),
      frame_bytes_(static_cast<std::size_t>(width) * height * 4) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
    throw std::runtime_error(
        "--video needs ffmpeg (Debian package ffmpeg; scripts/deps installs it)");
  char geometry[64], rate[32];
  std::snprintf(geometry, sizeof geometry, "%dx%d", width, height);
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  // yuv420p needs even sizes: pad by one pixel where needed.
  const std::string command =
      std::string("ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s ") +
      geometry + " -r " + rate +
      " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset medium -crf 18 "
      "-pix_fmt yuv420p -movflags +faststart " +
      shell_quote(temp_);
  // A dead ffmpeg must surface as a write error, not kill this process with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  pipe_ = ::popen(command.c_str(), "w");
  if (!pipe_) throw std::runtime_error("cannot start ffmpeg for '" + path + "'");
}

VideoPipe::~VideoPipe() {
  if (pipe_) {
    ::pclose(pipe_);
    std::remove(temp_.c_str());
  }
}

void VideoPipe::write(const std::vector<std::uint8_t>& rgba) {
  if (rgba.size() != frame_bytes_ || std::fwrite(rgba.data(), 1, rgba.size(), pipe_) != rgba.size())
    throw std::runtime_error("ffmpeg stopped accepting frames for '" + path_ + "'");
}

void VideoPipe::finish() {
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  if (status != 0 || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    std::remove(temp_.c_str());
    throw std::runtime_error("ffmpeg failed to write '" + path_ + "' (exit status " +
                             std::to_string(WEXITSTATUS(status)) + ")");
  }
}

}  // namespace clothlab::app
