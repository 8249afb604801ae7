// The checks tinyobjloader does not make, by a pass over the OBJ text before it reads the file:
// tinyobjloader reads a coordinate it cannot parse (`v a b c`, `v 1 nan 1`) or a missing one
// (`v -0.3 0`) as 0 and one beyond a float (`v 1e39 0 0`) as inf, and reports no line for them.
#pragma once

#include <string>
#include <vector>

namespace clothlab {

struct ObjScan {
  // The OBJ line of each face ("f ..."), in file order, and its corner count, so that the
  // triangles tinyobjloader fans a face into can be named by the line they came from.
  std::vector<int> face_lines, face_corners;
  // The OBJ line of each vertex ("v ..."), in file order.
  std::vector<int> vertex_lines;
};

// Throws ObjError ("path: line N: ...") for a vertex line whose x, y or z is missing, not a
// number, not finite, or beyond the largest float in magnitude.
ObjScan scan_obj(const std::string& path);

// The OBJ line of each triangle, when the faces fanned into `triangles` triangles (n - 2 for an
// n-corner face); empty when the count differs (the reader dropped or split faces otherwise).
std::vector<int> triangle_lines(const ObjScan& scan, std::size_t triangles);

}  // namespace clothlab
