#include <cstdio>
#include <sstream>

#include "export/part_writers.hpp"
#include "io/atomic_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

// Shortest text that reads back as the same float.
void put(std::ostringstream& s, float v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  s << buffer;
}

}  // namespace

std::vector<std::filesystem::path> writePartObj(const std::filesystem::path& objPath, const Mesh& mesh,
                                                const Image& texture) {
  if (!mesh.hasUvs()) throw InputError("internal: the part has no texture coordinates to write");
  const std::filesystem::path folder = objPath.parent_path();
  const std::string stem = objPath.stem().string();
  const std::filesystem::path mtlPath = folder / (stem + ".mtl"), pngPath = folder / (stem + ".png");

  writeImage(pngPath, texture);

  std::ostringstream mtl;
  mtl << "# Kerf: the block's wood baked onto the part\n"
      << "newmtl wood\nKa 1 1 1\nKd 1 1 1\nKs 0.04 0.04 0.04\nNs 40\nd 1\nillum 2\n"
      << "map_Kd " << pngPath.filename().string() << "\n";
  writeTextAtomically(mtlPath, mtl.str());

  std::ostringstream obj;
  obj << "# Kerf textured part: block frame, millimetres (docs/coordinates.md, docs/export.md)\n"
      << "mtllib " << mtlPath.filename().string() << "\n"
      << "o " << (mesh.name.empty() ? std::string("part") : mesh.name) << "\n";
  for (const glm::vec3& p : mesh.positions) {
    obj << "v ";
    put(obj, p.x), obj << ' ', put(obj, p.y), obj << ' ', put(obj, p.z), obj << '\n';
  }
  for (const glm::vec2& t : mesh.uvs) {
    obj << "vt ";
    put(obj, t.x), obj << ' ', put(obj, 1.0f - t.y), obj << '\n';
  }
  const bool normals = mesh.hasNormals();
  for (const glm::vec3& n : mesh.normals) {
    obj << "vn ";
    put(obj, n.x), obj << ' ', put(obj, n.y), obj << ' ', put(obj, n.z), obj << '\n';
  }
  obj << "usemtl wood\n";
  for (const glm::uvec3& t : mesh.triangles) {
    obj << 'f';
    for (int k = 0; k < 3; ++k) {
      const unsigned i = t[k] + 1;
      obj << ' ' << i << '/' << i;
      if (normals) obj << '/' << i;
    }
    obj << '\n';
  }
  writeTextAtomically(objPath, obj.str());
  return {objPath, mtlPath, pngPath};
}

}  // namespace kerf
