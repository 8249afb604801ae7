// A triangle mesh read from a Wavefront OBJ file (Debian's tinyobjloader): what mesh colliders
// (sim/mesh/sdf_grid.hpp) and, later, OBJ scenery and mesh cloth are built from.
#pragma once

#include <Eigen/Core>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace clothlab {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;  // polygons fanned into triangles
  std::vector<int> triangle_lines;            // each triangle's OBJ line (empty if not known)
};

// A file that cannot be read, is not valid OBJ, or has no faces. what() starts with the path
// (and the OBJ line where the reader names one).
class ObjError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads every face of every object in `path`, scaled by `scale` about the origin. Throws
// ObjError for a missing or unreadable file, a parse error, a vertex coordinate that is missing,
// not a number, not finite or beyond a float (sim/mesh/obj_scan.hpp), a face index outside the
// vertex list, or a file without faces.
TriangleMesh load_obj(const std::string& path, double scale = 1.0);

}  // namespace clothlab
