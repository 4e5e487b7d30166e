#include "mesh/mesh_normals.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <unordered_map>

namespace kerf {
namespace {

// Exact float bits as a hash key; +0.0f is added first so that -0 and +0 are one position.
template <std::size_t N>
struct BitsHash {
  std::size_t operator()(const std::array<std::uint32_t, N>& a) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t v : a) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

template <std::size_t N>
std::array<std::uint32_t, N> bitsOf(const float (&values)[N]) {
  std::array<std::uint32_t, N> out{};
  for (std::size_t i = 0; i < N; ++i) {
    const float v = values[i] + 0.0f;
    std::memcpy(&out[i], &v, sizeof v);
  }
  return out;
}

glm::vec3 unitOrZero(glm::vec3 v) {
  const float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

}  // namespace

void smoothNormalsAndJoinVertices(Mesh& mesh, const std::vector<bool>& needsNormal, float maxAngleDeg) {
  const std::size_t vertexCount = mesh.positions.size(), triangleCount = mesh.triangles.size();
  mesh.normals.resize(vertexCount, glm::vec3(0.0f, 0.0f, 1.0f));
  mesh.uvs.resize(vertexCount, glm::vec2(0.0f));

  // Corners welded by exact position.
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, BitsHash<3>> positionIds;
  positionIds.reserve(vertexCount);
  std::vector<std::uint32_t> weld(vertexCount);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    const glm::vec3 p = mesh.positions[v];
    const float key[3] = {p.x, p.y, p.z};
    weld[v] = positionIds.emplace(bitsOf(key), static_cast<std::uint32_t>(positionIds.size())).first->second;
  }
  const std::size_t weldedCount = positionIds.size();

  // Area-weighted triangle normals, and the triangles around each welded position (compressed rows).
  std::vector<glm::vec3> faceNormal(triangleCount);
  std::vector<std::uint32_t> rowStart(weldedCount + 1, 0);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const glm::uvec3 tri = mesh.triangles[t];
    faceNormal[t] = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                               mesh.positions[tri.z] - mesh.positions[tri.x]);
    for (int k = 0; k < 3; ++k) ++rowStart[weld[tri[k]] + 1];
  }
  for (std::size_t w = 0; w < weldedCount; ++w) rowStart[w + 1] += rowStart[w];
  std::vector<std::uint32_t> trianglesAt(rowStart.back());
  std::vector<std::uint32_t> filled(rowStart.begin(), rowStart.end() - 1);
  std::vector<glm::vec3> sumAt(weldedCount, glm::vec3(0.0f));
  for (std::size_t t = 0; t < triangleCount; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t w = weld[mesh.triangles[t][k]];
      trianglesAt[filled[w]++] = static_cast<std::uint32_t>(t);
      sumAt[w] += faceNormal[t];
    }

  // One normal per corner.
  const float cosLimit = std::cos(glm::radians(maxAngleDeg));
  std::vector<glm::vec3> cornerNormal(3 * triangleCount);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const glm::vec3 own = unitOrZero(faceNormal[t]);
    const bool ownless = own == glm::vec3(0.0f);  // a zero-area triangle takes its neighbours' normal
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      glm::vec3& out = cornerNormal[3 * t + k];
      if (!needsNormal[v]) {
        out = mesh.normals[v];
        continue;
      }
      const std::uint32_t w = weld[v];
      glm::vec3 sum(0.0f);
      if (rowStart[w + 1] - rowStart[w] <= static_cast<std::uint32_t>(kExactValence)) {
        for (std::uint32_t i = rowStart[w]; i < rowStart[w + 1]; ++i) {
          const glm::vec3 n = faceNormal[trianglesAt[i]];
          if (ownless || glm::dot(unitOrZero(n), own) >= cosLimit) sum += n;
        }
      } else {
        sum = ownless || glm::dot(unitOrZero(sumAt[w]), own) >= cosLimit ? sumAt[w] : faceNormal[t];
      }
      const glm::vec3 unit = unitOrZero(sum);
      out = unit != glm::vec3(0.0f) ? unit : (ownless ? glm::vec3(0.0f, 0.0f, 1.0f) : own);
    }
  }

  // Corners equal in position, normal and texture coordinate become one vertex.
  std::unordered_map<std::array<std::uint32_t, 8>, std::uint32_t, BitsHash<8>> vertexIds;
  vertexIds.reserve(vertexCount);
  Mesh joined;
  joined.name = mesh.name;
  joined.triangles.resize(triangleCount);
  for (std::size_t t = 0; t < triangleCount; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      const glm::vec3 p = mesh.positions[v], n = cornerNormal[3 * t + k];
      const glm::vec2 uv = mesh.uvs[v];
      const float key[8] = {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y};
      const auto [at, added] =
          vertexIds.emplace(bitsOf(key), static_cast<std::uint32_t>(joined.positions.size()));
      if (added) {
        joined.positions.push_back(p);
        joined.normals.push_back(n);
        joined.uvs.push_back(uv);
      }
      joined.triangles[t][k] = at->second;
    }
  mesh = std::move(joined);
}

}  // namespace kerf
