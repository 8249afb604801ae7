// The mutation driver's mutators: small, deterministic changes to an input, from a seeded
// generator (SplitMix64, Steele et al. 2014), so that a run is repeatable from its seed. Text
// inputs (scenes, OBJ) change mostly at the token level, where a parser's checks live: a number
// replaced by one of the values that broke ClothLab before (1e39, 1e-45, nan, 4294967296, ...),
// a line deleted, repeated or taken from another seed, a string replaced by a name the format
// knows. Binary inputs (sound files) change header fields and samples.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clothlab::fuzz {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n) (n > 0).
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t state_;
};

enum class InputKind { text, binary };

// One to four mutations of `input`; `others` (the seeds) feed the splicing mutators.
std::string mutate(const std::string& input, const std::vector<std::string>& others, InputKind kind,
                   Random& random);

}  // namespace clothlab::fuzz
