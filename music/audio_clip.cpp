#include "music/audio_clip.hpp"

#include <sndfile.h>

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "music/stderr_capture.hpp"
#include "sim/core/temp_files.hpp"

namespace clothlab {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};
using SndfilePtr = std::unique_ptr<SNDFILE, SndfileCloser>;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw AudioError("audio file '" + path + "': " + reason);
}

// The decoder's reason and what it printed: "reason (decoder: ...)".
std::string with_decoder_text(const std::string& reason, StderrCapture& capture) {
  const std::string printed = capture.text();
  return printed.empty() ? reason : reason + " (decoder: " + printed + ")";
}

}  // namespace

double AudioClip::duration() const {
  if (sample_rate <= 0) return 0.0;
  return static_cast<double>(samples.size()) / sample_rate;
}

AudioClip read_audio(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail(path, "no such file (or not a regular file)");
  StderrCapture capture;
  SF_INFO info{};
  SndfilePtr file(sf_open(path.c_str(), SFM_READ, &info));
  // sf_strerror(nullptr) reports why the last sf_open failed; for a file that exists, that it
  // does not exist is libsndfile's wording for "no decoder accepted it".
  if (!file) {
    const std::string why = sf_strerror(nullptr);
    const bool misleading = why.find("does not exist") != std::string::npos;
    fail(path, with_decoder_text("not a sound file libsndfile can decode" +
                                     (misleading ? std::string() : " (" + why + ")"),
                                 capture));
  }
  if (info.channels <= 0 || info.samplerate <= 0)
    fail(path, with_decoder_text("no channels or no sample rate", capture));

  AudioClip clip;
  clip.sample_rate = info.samplerate;
  if (info.frames > 0) clip.samples.reserve(static_cast<std::size_t>(info.frames));
  // Read in blocks until the decoder stops, rather than trusting info.frames: compressed
  // formats may report an estimate.
  constexpr sf_count_t kBlockFrames = 8192;
  const int channels = info.channels;
  std::vector<float> block(static_cast<std::size_t>(kBlockFrames * channels));
  for (;;) {
    const sf_count_t got = sf_readf_float(file.get(), block.data(), kBlockFrames);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i) {
      float sum = 0.0f;
      for (int c = 0; c < channels; ++c) sum += block[static_cast<std::size_t>(i * channels + c)];
      // A float WAV may hold inf or nan; the beat tracker and the dance would turn them to nan.
      if (!std::isfinite(sum))
        fail(path, "sample " + std::to_string(clip.samples.size()) +
                       " (t = " + std::to_string(double(clip.samples.size()) / info.samplerate) +
                       " s) is not finite");
      clip.samples.push_back(sum / static_cast<float>(channels));
    }
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR)
    fail(path, with_decoder_text(sf_strerror(file.get()), capture));
  if (clip.samples.empty()) fail(path, with_decoder_text("contains no samples", capture));
  return clip;
}

void write_wav(const std::string& path, const AudioClip& clip) {
  if (clip.sample_rate <= 0)
    fail(path, "cannot write a sample rate of " + std::to_string(clip.sample_rate));
  const std::string tmp = path + ".tmp";
  const TempFileGuard guard(tmp);  // removed on SIGINT / SIGTERM too
  SF_INFO info{};
  info.samplerate = clip.sample_rate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  {
    SndfilePtr file(sf_open(tmp.c_str(), SFM_WRITE, &info));
    if (!file) fail(path, std::string("cannot create '") + tmp + "': " + sf_strerror(nullptr));
    // Without clipping, libsndfile wraps a sample above full scale to a large negative one.
    sf_command(file.get(), SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const auto n = static_cast<sf_count_t>(clip.samples.size());
    const sf_count_t written = sf_writef_float(file.get(), clip.samples.data(), n);
    if (written != n) {
      const std::string reason = sf_strerror(file.get());
      file.reset();
      std::remove(tmp.c_str());
      fail(path, "write failed: " + reason);
    }
    // sf_close finalises the RIFF header; a failure here means a truncated file.
    if (sf_close(file.release()) != 0) {
      std::remove(tmp.c_str());
      fail(path, "closing '" + tmp + "' failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    fail(path, "cannot rename '" + tmp + "' to it");
  }
}

}  // namespace clothlab
