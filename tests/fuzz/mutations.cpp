#include "tests/fuzz/mutations.hpp"

#include <cctype>
#include <cmath>
#include <cstring>

namespace clothlab::fuzz {
namespace {

// Numbers that once got through, or sit on an edge of a range or a type.
const char* const kNumbers[] = {
    "0",    "-0.0",   "1",     "-1",         "2",          "1e39",        "-1e39",
    "1e38", "3.5e38", "1e-45", "1e-300",     "1e300",      "1e308",       "1e-20",
    "nan",  "inf",    "-inf",  "4294967296", "2147483647", "-2147483648", "9223372036854775807",
    "0.5",  "1e-9",   "65536", "100000",     "3",          "16000000",    "0.0001"};

// Strings and keys the scene format knows: every value of its choices, files, tables.
const char* const kWords[] = {"\"mesh\"",
                              "\"tube\"",
                              "\"grid\"",
                              "\"gpu\"",
                              "\"double\"",
                              "\"implicit_euler\"",
                              "\"vbd\"",
                              "\"bdf2\"",
                              "\"xpbd\"",
                              "\"local_global\"",
                              "\"rk4\"",
                              "\"verlet\"",
                              "\"seed_hack\"",
                              "\"auto\"",
                              "\"box\"",
                              "\"plane\"",
                              "\"capsule\"",
                              "\"sphere\"",
                              "\"newton\"",
                              "\"../assets/meshes/chair.obj\"",
                              "\"../assets/meshes/round_cloth.obj\"",
                              "\"\"",
                              "[]",
                              "[[]]",
                              "{}",
                              "true",
                              "false",
                              "[0, 0, 0]",
                              "[1e39, 0, 0]",
                              "[2, 2]",
                              "[1, 1]",
                              "[0, 0]"};

const char* const kLines[] = {"[music]",
                              "[mannequin]",
                              "[trace]",
                              "[[colliders]]",
                              "type = \"mesh\"",
                              "file = \"../assets/meshes/vase.obj\"",
                              "shape = \"tube\"",
                              "[[cloth]]",
                              "[cloth]",
                              "self_collision = true",
                              "backend = \"gpu\"",
                              "precision = \"double\"",
                              "pins_follow = \"pelvis\"",
                              "v 1e39 0 0",
                              "v nan 0 0",
                              "f 1 2 3",
                              "f 1 1 1",
                              "f -1 -2 -3",
                              "v 0 0",
                              "f 1 2 3 4 5 6 7 8"};

template <std::size_t N>
const char* pick(const char* const (&list)[N], Random& r) {
  return list[r.below(N)];
}

bool number_char(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
         c == '-' || c == '+';
}

// [begin, end) of a random run of number characters containing a digit, or begin == end.
std::pair<std::size_t, std::size_t> some_number(const std::string& s, Random& r) {
  for (int attempt = 0; attempt < 16 && !s.empty(); ++attempt) {
    std::size_t i = r.below(s.size());
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) continue;
    std::size_t b = i, e = i;
    while (b > 0 && number_char(s[b - 1])) --b;
    while (e < s.size() && number_char(s[e])) ++e;
    return {b, e};
  }
  return {0, 0};
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t end = s.find('\n', start);
    lines.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i)
    out += lines[i] + (i + 1 < lines.size() ? "\n" : "");
  return out;
}

std::string mutate_lines(const std::string& s, const std::vector<std::string>& others, Random& r) {
  std::vector<std::string> lines = lines_of(s);
  const std::size_t at = r.below(lines.size());
  switch (r.below(5)) {
    case 0:
      lines.erase(lines.begin() + long(at));
      break;
    case 1:
      lines.insert(lines.begin() + long(at), lines[at]);
      break;
    case 2:
      std::swap(lines[at], lines[r.below(lines.size())]);
      break;
    case 3: {
      const std::vector<std::string> other = lines_of(others[r.below(others.size())]);
      lines.insert(lines.begin() + long(at), other[r.below(other.size())]);
      break;
    }
    default:
      lines.insert(lines.begin() + long(at), pick(kLines, r));
  }
  return joined(lines);
}

std::string mutate_text(std::string s, const std::vector<std::string>& others, Random& r) {
  switch (r.below(8)) {
    case 0:
    case 1:
    case 2: {  // a number replaced: most of the checks are on numbers
      const auto [b, e] = some_number(s, r);
      if (b < e) s.replace(b, e - b, pick(kNumbers, r));
      return s;
    }
    case 3: {  // a value replaced by a known word (after an '=' or inside brackets)
      const std::size_t eq = s.find('=', s.empty() ? 0 : r.below(s.size()));
      if (eq == std::string::npos) return s;
      const std::size_t end = s.find('\n', eq);
      s.replace(eq + 1, (end == std::string::npos ? s.size() : end) - eq - 1,
                std::string(" ") + pick(kWords, r));
      return s;
    }
    case 4:
    case 5:
      return mutate_lines(s, others, r);
    case 6:  // a character changed, inserted or removed
      if (s.empty()) return s;
      switch (r.below(3)) {
        case 0:
          s[r.below(s.size())] = static_cast<char>(r.below(256));
          break;
        case 1:
          s.insert(r.below(s.size()), 1, "[]{}=\",.#\n\\'0"[r.below(14)]);
          break;
        default:
          s.erase(r.below(s.size()), 1);
      }
      return s;
    default:  // cut short
      return s.substr(0, s.empty() ? 0 : r.below(s.size()));
  }
}

// Little-endian field of `bytes` bytes at `at`.
void put(std::string& s, std::size_t at, std::uint64_t value, int bytes) {
  for (int k = 0; k < bytes && at + std::size_t(k) < s.size(); ++k)
    s[at + std::size_t(k)] = static_cast<char>((value >> (8 * k)) & 0xff);
}

std::string mutate_binary(std::string s, Random& r) {
  static const std::uint64_t kInts[] = {0,      1,          2,          3,  100, 7999, 8000, 44100,
                                        0xffff, 0x7fffffff, 0xffffffff, 16, 24,  32,   64};
  static const float kFloats[] = {INFINITY, -INFINITY, NAN, 3.4e38f, 1e-45f, 1.0f, -1.0f};
  if (s.empty()) return s;
  switch (r.below(5)) {
    case 0:  // a WAV header field: format, channels, rate, byte rate, block, bits, sizes
      put(s, std::vector<std::size_t>{4, 16, 20, 22, 24, 28, 32, 34, 40}[r.below(9)],
          kInts[r.below(std::size(kInts))], r.below(2) ? 2 : 4);
      return s;
    case 1: {  // a sample
      const float f = kFloats[r.below(std::size(kFloats))];
      std::uint32_t bits = 0;
      std::memcpy(&bits, &f, 4);
      put(s, 44 + 4 * r.below(s.size() / 4 + 1), bits, 4);
      return s;
    }
    case 2:
      s[r.below(s.size())] ^= static_cast<char>(1u << r.below(8));
      return s;
    case 3:
      return s.substr(0, r.below(s.size()));
    default:
      for (int k = 0, n = int(r.below(64)); k < n; ++k)
        s.push_back(static_cast<char>(r.below(256)));
      return s;
  }
}

}  // namespace

std::string mutate(const std::string& input, const std::vector<std::string>& others, InputKind kind,
                   Random& random) {
  std::string s = input;
  for (std::size_t n = 1 + random.below(4); n > 0; --n)
    s = kind == InputKind::text ? mutate_text(std::move(s), others, random)
                                : mutate_binary(std::move(s), random);
  return s;
}

}  // namespace clothlab::fuzz
