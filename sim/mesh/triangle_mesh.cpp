#include "sim/mesh/triangle_mesh.hpp"

#include "sim/mesh/obj_scan.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace clothlab {

TriangleMesh load_obj(const std::string& path, double scale) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(st)) throw ObjError(path + ": no such OBJ file");
  if (std::filesystem::is_directory(st)) throw ObjError(path + ": a directory, not an OBJ file");
  if (!std::filesystem::is_regular_file(st))
    throw ObjError(path + ": a device, pipe or socket, not an OBJ file");
  if (!std::ifstream(path)) throw ObjError(path + ": cannot open OBJ file");
  const ObjScan scan = scan_obj(path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // tinyobjloader reports problems as text, with the OBJ line where it knows it.
  if (!reader.ParseFromFile(path, config) || !reader.Error().empty()) {
    std::string message = reader.Error();
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
      message.pop_back();
    throw ObjError(path + ": not a valid OBJ file (" +
                   (message.empty() ? std::string("the reader gave no reason") : message) + ")");
  }
  TriangleMesh mesh;
  const std::vector<float>& v = reader.GetAttrib().vertices;
  static const char* kAxes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    // The scan checked the text with strtod; tinyobjloader parses numbers its own way and reads
    // some that strtod takes as finite as nan ("0.e7000": 0 times 10^7000), so check its values.
    for (std::size_t a = 0; a < 3; ++a) {
      if (std::isfinite(v[i + a])) continue;
      const std::size_t k = i / 3;
      const std::string line =
          k < scan.vertex_lines.size() ? "line " + std::to_string(scan.vertex_lines[k]) + ": " : "";
      throw ObjError(path + ": " + line + "vertex " + kAxes[a] +
                     " coordinate is not finite as the OBJ reader reads it (" +
                     (std::isnan(v[i + a]) ? "nan" : "infinite") + ")");
    }
    mesh.positions.emplace_back(scale * v[i], scale * v[i + 1], scale * v[i + 2]);
  }
  const int count = static_cast<int>(mesh.positions.size());
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t f = 0; f + 2 < indices.size(); f += 3) {
      std::array<int, 3> t{indices[f].vertex_index, indices[f + 1].vertex_index,
                           indices[f + 2].vertex_index};
      for (int k : t)
        if (k < 0 || k >= count)
          throw ObjError(path + ": face " + std::to_string(mesh.triangles.size() + 1) +
                         " names vertex " + std::to_string(k + 1) + ", but the file has " +
                         std::to_string(count) + " vertices");
      mesh.triangles.push_back(t);
    }
  }
  if (mesh.triangles.empty()) throw ObjError(path + ": the OBJ file has no faces");
  mesh.triangle_lines = triangle_lines(scan, mesh.triangles.size());
  return mesh;
}

}  // namespace clothlab
