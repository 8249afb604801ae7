// Frames into an MP4 through Debian's ffmpeg (H.264, yuv420p): raw RGBA frames go down a pipe,
// with the scene's music, where it has one, muxed in as AAC.
// The video is written to a temporary file and renamed when ffmpeg succeeds: complete or absent.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "music/audio_clip.hpp"
#include "sim/core/temp_files.hpp"

namespace clothlab::app {

// The sound under the frames: the clip's sample at time t plays with the frame shown at t (frame
// n at n / fps), cut to `seconds` or padded with silence where the clip is shorter.
struct VideoMusic {
  const AudioClip* clip = nullptr;  // none: a video without an audio stream
  double seconds = 0.0;             // the video's length, frames / fps
};

class VideoPipe {
 public:
  // Throws std::runtime_error when ffmpeg cannot be started or the music cannot be written
  // (it goes to ffmpeg as a temporary WAV beside `path`, removed when the pipe closes).
  VideoPipe(const std::string& path, int width, int height, double fps,
            const VideoMusic& music = {});
  ~VideoPipe();
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  void write(const std::vector<std::uint8_t>& rgba);
  // Closes the pipe; throws if ffmpeg failed. Renames the temporary file into place.
  void finish();

 private:
  // Removes its file when destroyed, so the WAV goes even when the constructor throws later.
  struct TempFile {
    std::string path;
    ~TempFile();
  };

  std::string path_, temp_;
  TempFileGuard temp_guard_{temp_};  // both removed on SIGINT / SIGTERM too
  std::optional<TempFileGuard> wav_guard_;
  TempFile music_wav_;
  std::FILE* pipe_ = nullptr;
  std::size_t frame_bytes_;
};

}  // namespace clothlab::app
