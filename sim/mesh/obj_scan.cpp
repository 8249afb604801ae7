#include "sim/mesh/obj_scan.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "sim/mesh/triangle_mesh.hpp"

namespace clothlab {
namespace {

// The problem with one coordinate token, or "" when it is a finite number within float range.
std::string coordinate_problem(const std::string& token) {
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if (end == token.c_str() || *end != '\0') return "\"" + token + "\" is not a number";
  if (!std::isfinite(x)) return "\"" + token + "\" is not finite";
  if (std::abs(x) > std::numeric_limits<float>::max())
    return token + " is beyond the largest float (3.4e+38)";
  return "";
}

// The problem with one face corner ("v", "v/vt", "v//vn", "v/vt/vn"), or "" when each index it
// gives is a non-zero integer within int range (OBJ counts from 1; negative counts back).
// tinyobjloader reads indices into an int without a range check: 4294967297 wrapped to 1.
std::string corner_problem(const std::string& corner) {
  std::size_t at = 0;
  for (int field = 0; at <= corner.size(); ++field) {
    const std::size_t slash = std::min(corner.find('/', at), corner.size());
    const std::string index = corner.substr(at, slash - at);
    at = slash + 1;
    if (index.empty() && field > 0) continue;  // "v//vn": no texture index
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(index.c_str(), &end, 10);
    if (index.empty() || *end != '\0') return "\"" + corner + "\" is not a face corner";
    if (errno == ERANGE || i == 0 || i > std::numeric_limits<int>::max() ||
        i < -std::numeric_limits<int>::max())
      return "\"" + corner + "\" has index " + index +
             ", outside 1..2147483647 (or -1..-2147483647 from the end)";
  }
  return "";
}

// The next line, ended by \n, \r\n or a lone \r (tinyobjloader ends a line at \r too, so a
// vertex hidden behind one must be seen here).
bool next_line(std::istream& in, std::string& line) {
  line.clear();
  int c = in.get();
  if (c == EOF) return false;
  for (; c != EOF && c != '\n' && c != '\r'; c = in.get()) line.push_back(static_cast<char>(c));
  if (c == '\r' && in.peek() == '\n') in.get();
  return true;
}

}  // namespace

ObjScan scan_obj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  ObjScan scan;
  std::string line, word, token;
  static const char* kAxes[] = {"x", "y", "z"};
  for (int number = 1; next_line(in, line); ++number) {
    std::istringstream words(line);
    if (!(words >> word)) continue;
    if (word == "f") {
      int corners = 0;
      while (words >> token) {
        ++corners;
        const std::string problem = corner_problem(token);
        if (!problem.empty())
          throw ObjError(path + ": line " + std::to_string(number) + ": face corner " + problem);
      }
      scan.face_lines.push_back(number);
      scan.face_corners.push_back(corners);
      continue;
    }
    if (word != "v") continue;
    scan.vertex_lines.push_back(number);
    for (int a = 0; a < 3; ++a) {
      const std::string where = path + ": line " + std::to_string(number) + ": vertex ";
      if (!(words >> token)) throw ObjError(where + "has no " + kAxes[a] + " coordinate");
      const std::string problem = coordinate_problem(token);
      if (!problem.empty()) throw ObjError(where + kAxes[a] + " coordinate " + problem);
    }
  }
  return scan;
}

std::vector<int> triangle_lines(const ObjScan& scan, std::size_t triangles) {
  std::vector<int> lines;
  for (std::size_t f = 0; f < scan.face_lines.size(); ++f)
    for (int t = 0; t + 2 < scan.face_corners[f]; ++t) lines.push_back(scan.face_lines[f]);
  if (lines.size() != triangles) lines.clear();
  return lines;
}

}  // namespace clothlab
