// Sound files through libsndfile: a WAV round trip within 16-bit quantisation, FLAC and stereo
// decoding, errors that name the file, and atomic writes (complete file or none).
#include <gtest/gtest.h>
#include <sndfile.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "music/audio_clip.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test and process: ctest runs tests of one binary side by side.
fs::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       ("clothlab_audio_" + std::to_string(getpid()) + "_" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

AudioClip sine_clip(int sample_rate, double seconds, double hz, double amplitude) {
  AudioClip clip;
  clip.sample_rate = sample_rate;
  clip.samples.resize(static_cast<std::size_t>(seconds * sample_rate));
  for (std::size_t i = 0; i < clip.samples.size(); ++i)
    clip.samples[i] =
        static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * hz * i / sample_rate));
  return clip;
}

// Writes interleaved frames with libsndfile directly, in any format it supports.
void write_with_sndfile(const fs::path& path, int format, int channels, int sample_rate,
                        const std::vector<float>& interleaved) {
  SF_INFO info{};
  info.samplerate = sample_rate;
  info.channels = channels;
  info.format = format;
  SNDFILE* f = sf_open(path.c_str(), SFM_WRITE, &info);
  ASSERT_NE(f, nullptr) << sf_strerror(nullptr);
  const auto frames = static_cast<sf_count_t>(interleaved.size() / channels);
  EXPECT_EQ(sf_writef_float(f, interleaved.data(), frames), frames);
  sf_close(f);
}

TEST(AudioClip, DurationIsSamplesOverRate) {
  EXPECT_DOUBLE_EQ(sine_clip(8000, 1.5, 440.0, 0.5).duration(), 1.5);
  EXPECT_DOUBLE_EQ(AudioClip{}.duration(), 0.0);
}

TEST(AudioClip, WavRoundTripKeepsLengthRateAndValuesWithin16BitSteps) {
  const fs::path dir = test_dir();
  const std::string path = (dir / "tone.wav").string();
  AudioClip clip = sine_clip(22050, 0.75, 441.0, 0.8);
  clip.samples[10] = 1.5f;  // above full scale: clipped to +1, not wrapped to negative
  write_wav(path, clip);
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const AudioClip back = read_audio(path);
  EXPECT_EQ(back.sample_rate, 22050);
  ASSERT_EQ(back.samples.size(), clip.samples.size());
  // One 16-bit step is 2^-15; libsndfile scales by 32767 on writing and 32768 on reading.
  const double step = 1.0 / 32768.0;
  double worst = 0.0;
  for (std::size_t i = 0; i < clip.samples.size(); ++i) {
    if (i == 10) continue;
    worst = std::max(worst, static_cast<double>(std::abs(back.samples[i] - clip.samples[i])));
  }
  EXPECT_LE(worst, 1.5 * step);
  EXPECT_GT(worst, 0.0);  // really quantised: the file is 16-bit, not float
  EXPECT_NEAR(back.samples[10], 1.0, 2.0 * step);
  fs::remove_all(dir);
}

TEST(AudioClip, FlacReadsBack) {
  const fs::path dir = test_dir();
  const fs::path path = dir / "tone.flac";
  const AudioClip clip = sine_clip(48000, 0.5, 1000.0, 0.5);
  write_with_sndfile(path, SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, 48000, clip.samples);
  const AudioClip back = read_audio(path.string());
  EXPECT_EQ(back.sample_rate, 48000);
  ASSERT_EQ(back.samples.size(), clip.samples.size());
  for (std::size_t i = 0; i < clip.samples.size(); i += 97)
    EXPECT_NEAR(back.samples[i], clip.samples[i], 2.0 / 32768.0) << "sample " << i;
  fs::remove_all(dir);
}

TEST(AudioClip, StereoIsMixedToMono) {
  const fs::path dir = test_dir();
  const fs::path path = dir / "stereo.wav";
  std::vector<float> interleaved;
  for (int i = 0; i < 1000; ++i) {
    interleaved.push_back(0.5f);                         // left: constant
    interleaved.push_back(i % 2 == 0 ? 0.25f : -0.25f);  // right: alternating
  }
  write_with_sndfile(path, SF_FORMAT_WAV | SF_FORMAT_FLOAT, 2, 44100, interleaved);
  const AudioClip back = read_audio(path.string());
  ASSERT_EQ(back.samples.size(), 1000u);
  EXPECT_FLOAT_EQ(back.samples[0], 0.375f);
  EXPECT_FLOAT_EQ(back.samples[1], 0.125f);
  EXPECT_FLOAT_EQ(back.samples[998], 0.375f);
  fs::remove_all(dir);
}

void expect_error_naming(const std::string& path, const std::string& reason_part) {
  try {
    read_audio(path);
    ADD_FAILURE() << "no AudioError for " << path;
  } catch (const AudioError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find(reason_part), std::string::npos) << what;
  }
}

TEST(AudioClip, MissingFileThrowsWithPath) {
  const fs::path dir = test_dir();
  expect_error_naming((dir / "no_such_song.wav").string(), "no such file");
  fs::remove_all(dir);
}

TEST(AudioClip, TextFileNamedWavThrowsWithPath) {
  const fs::path dir = test_dir();
  const fs::path path = dir / "notes.wav";
  std::ofstream(path) << "this is not a sound file, just some text\n";
  expect_error_naming(path.string(), "Format not recognised");
  fs::remove_all(dir);
}

std::size_t open_descriptors() {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

// Reading, good file or bad, leaves no descriptor open: the stderr capture's temporary file was
// never closed, one descriptor per read, until the fuzz pass ran out of them (EMFILE) after
// about 20 000 sound files.
TEST(AudioClip, ReadingLeavesNoDescriptorOpen) {
  const fs::path dir = test_dir();
  const std::string good = (dir / "tone.wav").string(), bad = (dir / "notes.wav").string();
  write_wav(good, sine_clip(8000, 0.1, 441.0, 0.5));
  std::ofstream(bad) << "not a sound file\n";
  (void)read_audio(good);  // libsndfile's own one-time set-up, if any, before counting
  const std::size_t before = open_descriptors();
  for (int k = 0; k < 20; ++k) {
    EXPECT_EQ(read_audio(good).sample_rate, 8000);
    EXPECT_THROW(read_audio(bad), AudioError);
  }
  EXPECT_EQ(open_descriptors(), before);
  fs::remove_all(dir);
}

TEST(AudioClip, EmptySoundFileThrowsWithPath) {
  const fs::path dir = test_dir();
  const fs::path path = dir / "empty.wav";
  write_with_sndfile(path, SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1, 44100, {});
  expect_error_naming(path.string(), "no samples");
  fs::remove_all(dir);
}

TEST(AudioClip, FailedWriteThrowsWithPathAndLeavesNothing) {
  const fs::path dir = test_dir();
  const fs::path path = dir / "missing_folder" / "out.wav";
  try {
    write_wav(path.string(), sine_clip(8000, 0.1, 440.0, 0.5));
    ADD_FAILURE() << "no AudioError";
  } catch (const AudioError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
  fs::remove_all(dir);
}

TEST(AudioClip, OverwriteReplacesWholeFileAndLeavesNoTemporary) {
  const fs::path dir = test_dir();
  const std::string path = (dir / "song.wav").string();
  write_wav(path, sine_clip(8000, 2.0, 440.0, 0.5));
  write_wav(path, sine_clip(8000, 0.5, 440.0, 0.5));
  EXPECT_EQ(read_audio(path).samples.size(), 4000u);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  }
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clothlab
