#include "apps/view/audio_playback.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "music/stderr_capture.hpp"

namespace clothlab::vis {
namespace {

std::string al_error_text(const char* call, ALenum error) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(error));
  return std::string("audio: OpenAL error ") + code + " in " + call;
}

// Full scale maps to +-32767, as libsndfile writes 16-bit PCM; clipped, not wrapped.
std::vector<std::int16_t> to_pcm16(const std::vector<float>& samples) {
  std::vector<std::int16_t> pcm(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
    pcm[i] = static_cast<std::int16_t>(std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32767.0f));
  return pcm;
}

}  // namespace

std::optional<AudioPlayback> AudioPlayback::open(const AudioClip& clip, std::string& message) {
  if (clip.samples.empty() || clip.sample_rate <= 0) {
    message = "audio: the clip is empty";
    return std::nullopt;
  }
  const std::size_t bytes = clip.samples.size() * sizeof(std::int16_t);
  if (bytes > static_cast<std::size_t>(std::numeric_limits<ALsizei>::max())) {
    message = "audio: the clip is too long for one OpenAL buffer";
    return std::nullopt;
  }
  AudioPlayback p;  // released by its destructor on every early return
  {
    // The back-ends OpenAL tries print their failures (ALSA: a dozen lines without a sound
    // card); they come back as one quoted line in the message when no device opens, and are
    // dropped when one does. Opening happens on the window's thread before playback starts.
    StderrCapture capture;
    p.device_ = alcOpenDevice(nullptr);
    if (p.device_) p.context_ = alcCreateContext(p.device_, nullptr);
    const bool current = p.context_ && alcMakeContextCurrent(p.context_) == ALC_TRUE;
    if (!current) {
      const std::string printed = capture.text();
      message = p.device_ ? "audio: OpenAL could not create a context on the default device"
                          : "audio: no output device (OpenAL could not open the default device)";
      if (!printed.empty())
        message += " (" + (printed.size() > 160 ? printed.substr(0, 157) + "..." : printed) + ")";
      return std::nullopt;
    }
  }
  alGetError();  // clear any stale error before our own calls
  auto al_failed = [&message](const char* call) {
    const ALenum e = alGetError();
    if (e != AL_NO_ERROR) message = al_error_text(call, e);
    return e != AL_NO_ERROR;
  };
  alGenBuffers(1, &p.buffer_);
  if (al_failed("alGenBuffers")) return std::nullopt;
  p.has_buffer_ = true;
  const std::vector<std::int16_t> pcm = to_pcm16(clip.samples);
  alBufferData(p.buffer_, AL_FORMAT_MONO16, pcm.data(), static_cast<ALsizei>(bytes),
               clip.sample_rate);
  if (al_failed("alBufferData")) return std::nullopt;
  alGenSources(1, &p.source_);
  if (al_failed("alGenSources")) return std::nullopt;
  p.has_source_ = true;
  alSourcei(p.source_, AL_BUFFER, static_cast<ALint>(p.buffer_));
  if (al_failed("alSourcei")) return std::nullopt;
  p.duration_ = clip.duration();
  message.clear();
  return std::optional<AudioPlayback>(std::move(p));
}

AudioPlayback::AudioPlayback(AudioPlayback&& other) noexcept {
  *this = std::move(other);
}

AudioPlayback& AudioPlayback::operator=(AudioPlayback&& other) noexcept {
  if (this == &other) return *this;
  release();
  device_ = std::exchange(other.device_, nullptr);
  context_ = std::exchange(other.context_, nullptr);
  source_ = std::exchange(other.source_, 0);
  buffer_ = std::exchange(other.buffer_, 0);
  has_source_ = std::exchange(other.has_source_, false);
  has_buffer_ = std::exchange(other.has_buffer_, false);
  duration_ = other.duration_;
  held_ = other.held_;
  started_ = other.started_;
  return *this;
}

AudioPlayback::~AudioPlayback() {
  release();
}

// Source before buffer (a buffer attached to a source cannot be deleted), both while the context
// is current, then the context (not while current) and the device.
void AudioPlayback::release() {
  if (context_) alcMakeContextCurrent(context_);
  if (has_source_) {
    alSourceStop(source_);
    alDeleteSources(1, &source_);
  }
  if (has_buffer_) alDeleteBuffers(1, &buffer_);
  has_source_ = has_buffer_ = false;
  if (context_) {
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(context_);
    context_ = nullptr;
  }
  if (device_) {
    alcCloseDevice(device_);
    device_ = nullptr;
  }
}

ALint AudioPlayback::state() const {
  ALint s = AL_INITIAL;
  if (has_source_) alGetSourcei(source_, AL_SOURCE_STATE, &s);
  return s;
}

bool AudioPlayback::playing() const {
  return state() == AL_PLAYING;
}

bool AudioPlayback::play() {
  if (!has_source_) return false;
  alGetError();
  const ALint s = state();
  if (s == AL_PLAYING) return true;
  if (s != AL_PAUSED) {
    // Initial or stopped: OpenAL applies an offset set now when play starts (AL 1.1, 4.3.2).
    double from = (s == AL_STOPPED && started_) ? duration_ : held_;
    if (from >= duration_) from = 0.0;  // played to the end: start again
    alSourceRewind(source_);
    alSourcef(source_, AL_SEC_OFFSET, static_cast<ALfloat>(from));
  }
  alSourcePlay(source_);
  started_ = true;
  return alGetError() == AL_NO_ERROR;
}

bool AudioPlayback::pause() {
  if (!has_source_) return false;
  alGetError();
  if (state() == AL_PLAYING) alSourcePause(source_);
  return alGetError() == AL_NO_ERROR;
}

bool AudioPlayback::seek(double seconds) {
  if (!has_source_) return false;
  alGetError();
  seconds = std::clamp(seconds, 0.0, duration_);
  const ALint s = state();
  if (s == AL_PLAYING || s == AL_PAUSED) {
    if (seconds >= duration_) {
      alSourceStop(source_);  // at the end: time() reports duration()
      started_ = true;
    } else {
      alSourcef(source_, AL_SEC_OFFSET, static_cast<ALfloat>(seconds));
    }
  } else {
    alSourceRewind(source_);  // back to initial, so time() reports the held position
    held_ = seconds;
    started_ = false;
  }
  return alGetError() == AL_NO_ERROR;
}

double AudioPlayback::time() const {
  const ALint s = state();
  if (s == AL_PLAYING || s == AL_PAUSED) {
    ALfloat offset = 0.0f;
    alGetSourcef(source_, AL_SEC_OFFSET, &offset);
    return std::min(static_cast<double>(offset), duration_);
  }
  if (s == AL_STOPPED && started_) return duration_;
  return held_;
}

}  // namespace clothlab::vis
