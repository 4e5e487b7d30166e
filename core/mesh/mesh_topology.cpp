#include "mesh/mesh_topology.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace kerf {
namespace {

struct PositionHash {
  std::size_t operator()(const glm::vec3& p) const {
    const auto bits = [](float f) {
      return std::uint64_t(std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f));
    };
    return std::size_t((bits(p.x) * 0x9E3779B97F4A7C15ull) ^ (bits(p.y) * 0xC2B2AE3D27D4EB4Full) ^
                       (bits(p.z) * 0x165667B19E3779F9ull));
  }
};

std::string pointText(glm::vec3 p) {
  std::ostringstream s;
  s.precision(4);
  s << p.x << ", " << p.y << ", " << p.z << " mm";
  return s.str();
}

}  // namespace

std::string MeshTopology::describeOpen() const {
  if (openEdges == 0) return {};
  std::ostringstream s;
  s << openEdges << " open edge" << (openEdges == 1 ? "" : "s") << " (a hole or a surface, e.g. at "
    << pointText(firstOpen) << ")";
  return s.str();
}

MeshTopology meshTopology(const Mesh& mesh) {
  // Weld corners that share a position exactly (+0 and -0 alike).
  std::unordered_map<glm::vec3, std::uint32_t, PositionHash> ids;
  ids.reserve(mesh.positions.size());
  std::vector<std::uint32_t> welded(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    glm::vec3 p = mesh.positions[i];
    for (int a = 0; a < 3; ++a)
      if (p[a] == 0.0f) p[a] = 0.0f;
    welded[i] = ids.emplace(p, static_cast<std::uint32_t>(ids.size())).first->second;
  }
  // Each edge as (smaller id, larger id), sorted, then counted in runs.
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  MeshTopology t;
  for (const glm::uvec3& tri : mesh.triangles) {
    const std::uint32_t v[3] = {welded[tri.x], welded[tri.y], welded[tri.z]};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      ++t.degenerateTriangles;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = std::min(v[k], v[(k + 1) % 3]), b = std::max(v[k], v[(k + 1) % 3]);
      edges.push_back(std::uint64_t(a) << 32 | b);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<glm::vec3> positionOf(ids.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) positionOf[welded[i]] = mesh.positions[i];
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const std::size_t count = j - i;
    const glm::vec3 mid =
        0.5f * (positionOf[edges[i] >> 32] + positionOf[static_cast<std::uint32_t>(edges[i])]);
    ++t.edges;
    if (count == 1 && t.openEdges++ == 0) t.firstOpen = mid;
    if (count > 2 && t.nonManifoldEdges++ == 0) t.firstNonManifold = mid;
    i = j;
  }
  return t;
}

}  // namespace kerf
