#pragma once
// A triangle mesh as Kerf uses it for parts (issue 7): indexed triangles with optional per-vertex normals
// and texture coordinates. Units are whatever the file used; Kerf reads them as millimetres.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace kerf {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty or one per position, unit length
  std::vector<glm::vec2> uvs;      // empty or one per position; (0, 0) = the texture's top-left corner
  std::vector<glm::uvec3> triangles;
  std::string name;  // for messages: usually the file it came from

  bool hasNormals() const { return !normals.empty() && normals.size() == positions.size(); }
  bool hasUvs() const { return !uvs.empty() && uvs.size() == positions.size(); }
};

struct MeshBounds {
  glm::vec3 min{0.0f}, max{0.0f};
  glm::vec3 centre() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
};
// The axis-aligned box around every position (zero box for an empty mesh).
MeshBounds meshBounds(const std::vector<glm::vec3>& positions);

}  // namespace kerf
