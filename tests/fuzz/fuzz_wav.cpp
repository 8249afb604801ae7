// A sound file as a scene's [music], with the mannequin dancing to its beats.
#include <cmath>
#include <fstream>
#include <string>

#include "load/scene_load.hpp"
#include "music/music_track.hpp"
#include "sim/body/body_motion.hpp"
#include "sim/scene/scene_error.hpp"
#include "tests/fuzz/fuzz_targets.hpp"

namespace clothlab::fuzz {
namespace {

void check_music(const MusicTrack& track) {
  for (float s : track.clip.samples)
    if (!std::isfinite(s)) finding("a sound that was read has a non-finite sample");
  for (double b : track.analysis.beats)
    if (!std::isfinite(b)) finding("a beat time is not finite");
}

// The dance's poses over its first ten seconds (the NaN poses began at 1.5 s).
void check_dance(const BodyMotion& body) {
  for (double t = 0.0; t <= 10.0; t += 0.125)
    for (int part = 0; part < body.part_count(); ++part) {
      const RigidState s = body.state(part, t);
      if (!s.position.allFinite() || !s.velocity.allFinite() || !s.rotation.coeffs().allFinite())
        finding("the dance's pose is not finite at t = " + std::to_string(t));
    }
}

}  // namespace

int fuzz_wav(const std::uint8_t* data, std::size_t size) {
  const std::string path = context().scratch_dir + "/fuzz.wav";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), long(size));
  Scene scene;
  try {
    scene = read_scene_string(
        "[cloth]\nresolution = [4, 4]\n[music]\nfile = \"fuzz.wav\"\n"
        "[mannequin]\n",
        context().scratch_dir + "/fuzz.toml");
  } catch (const SceneError&) {
    return 0;
  }
  check_music(*scene.music->track);
  check_dance(*scene.mannequin->motion);
  return 0;
}

}  // namespace clothlab::fuzz
