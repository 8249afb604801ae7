#include "sim/mesh/obj_scan.hpp"

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
      while (words >> token) ++corners;
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
