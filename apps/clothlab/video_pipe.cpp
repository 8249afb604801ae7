#include "apps/clothlab/video_pipe.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
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

// The music for a video of `seconds`: its first `seconds` plus a quarter second (so the AAC
// encoder's last frame has real samples and `-t` does the exact cut), zeros where it ends early.
// Writing only this part keeps a 40 s track from costing a 40 s WAV for a one-second video.
AudioClip music_for_video(const AudioClip& clip, double seconds) {
  AudioClip part;
  part.sample_rate = clip.sample_rate;
  const auto n = static_cast<std::size_t>(std::ceil((seconds + 0.25) * clip.sample_rate));
  part.samples.assign(n, 0.0f);
  std::copy_n(clip.samples.begin(), std::min(n, clip.samples.size()), part.samples.begin());
  return part;
}

// Whether ffprobe (Debian's ffmpeg package) reads `path` as a video. ffmpeg can exit 0 after
// failing to write an MP4's index (the moov atom at the end: "Error writing trailer ... No space
// left on device"), leaving a file no player opens.
bool readable_video(const std::string& path) {
  const std::string command = "ffprobe -v error -show_entries format=duration -of csv=p=0 " +
                              shell_quote(path) + " >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

}  // namespace

VideoPipe::TempFile::~TempFile() {
  if (!path.empty()) std::remove(path.c_str());
}

VideoPipe::VideoPipe(const std::string& path, int width, int height, double fps,
                     const VideoMusic& music)
    : path_(path),
      temp_(path + ".tmp." + std::to_string(::getpid()) + ".mp4"),
      frame_bytes_(static_cast<std::size_t>(width) * height * 4) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
    throw std::runtime_error(
        "--video needs ffmpeg (Debian package ffmpeg; scripts/deps installs it)");
  char geometry[64], rate[32];
  std::snprintf(geometry, sizeof geometry, "%dx%d", width, height);
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  std::string audio_input, audio_output;
  if (music.clip) {
    music_wav_.path = path + ".tmp." + std::to_string(::getpid()) + ".wav";
    wav_guard_.emplace(music_wav_.path);
    try {
      write_wav(music_wav_.path, music_for_video(*music.clip, music.seconds));
    } catch (const AudioError& e) {
      throw std::runtime_error("cannot write the music for '" + path + "': " + e.what());
    }
    char length[32];
    std::snprintf(length, sizeof length, "%.9g", music.seconds);
    // Both inputs start at time 0, so frame n (n / fps) plays with the music at n / fps; -t
    // cuts the output to the video's length.
    audio_input = " -i " + shell_quote(music_wav_.path);
    audio_output = std::string(" -map 0:v -map 1:a -c:a aac -b:a 160k -t ") + length;
  }
  // yuv420p needs even sizes: pad by one pixel where needed.
  const std::string command =
      std::string("ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s ") +
      geometry + " -r " + rate + " -i -" + audio_input +
      " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset medium -crf 18 "
      "-pix_fmt yuv420p" +
      audio_output + " -movflags +faststart " + shell_quote(temp_);
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
  // ffmpeg has read the music; the WAV goes now rather than when the pipe is destroyed.
  if (!music_wav_.path.empty()) std::remove(music_wav_.path.c_str());
  music_wav_.path.clear();
  if (status == 0 && !readable_video(temp_)) {
    std::remove(temp_.c_str());
    throw std::runtime_error("ffmpeg wrote an incomplete video for '" + path_ +
                             "' (no player could open it: is the disk full?); nothing was kept");
  }
  if (status != 0 || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    std::remove(temp_.c_str());
    throw std::runtime_error("ffmpeg failed to write '" + path_ + "' (exit status " +
                             std::to_string(WEXITSTATUS(status)) + ")");
  }
}

}  // namespace clothlab::app
