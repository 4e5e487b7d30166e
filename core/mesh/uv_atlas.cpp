#include "mesh/uv_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <numeric>
#include <unordered_map>

#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

// Vertices at the same position get one id, so charts connect across files that repeat vertices.
std::vector<int> weldByPosition(const std::vector<glm::vec3>& positions) {
  struct Hash {
    std::size_t operator()(const glm::vec3& p) const {
      std::uint32_t b[3];
      std::memcpy(b, &p, sizeof b);
      return (std::size_t(b[0]) * 73856093u) ^ (std::size_t(b[1]) * 19349663u) ^
             (std::size_t(b[2]) * 83492791u);
    }
  };
  std::unordered_map<glm::vec3, int, Hash> ids;
  std::vector<int> welded(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    welded[i] = ids.emplace(positions[i], static_cast<int>(ids.size())).first->second;
  return welded;
}

int dominantAxis(glm::vec3 n) {
  const glm::vec3 a = glm::abs(n);
  const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
  return axis * 2 + (n[axis] < 0.0f ? 1 : 0);
}

// The two block axes a chart along `axis` (0..5) is projected onto.
glm::vec2 project(glm::vec3 p, int axis) {
  switch (axis / 2) {
    case 0:
      return {p.y, p.z};
    case 1:
      return {p.z, p.x};
    default:
      return {p.x, p.y};
  }
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

struct ChartShape {
  std::vector<int> triangles;
  int axis = 0;
  glm::vec2 min{0.0f}, max{0.0f};  // projected extent, mm
};

ChartShape chartOf(const Mesh& mesh, std::vector<int> triangles, int axis) {
  ChartShape c;
  c.triangles = std::move(triangles);
  c.axis = axis;
  c.min = glm::vec2(INFINITY);
  c.max = glm::vec2(-INFINITY);
  for (int t : c.triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::vec2 q = project(mesh.positions[mesh.triangles[t][k]], axis);
      c.min = glm::min(c.min, q);
      c.max = glm::max(c.max, q);
    }
  return c;
}

// Whether two triangles of the chart cover the same point of its projection (a surface that winds round
// its axis, like a helical ramp): the projection is sampled on a grid of up to 512 cells a side, finer
// for charts of more triangles, and a cell centre strictly inside two triangles is an overlap.
bool projectionOverlaps(const Mesh& mesh, const ChartShape& c) {
  if (c.triangles.size() < 2) return false;
  const glm::vec2 extent = c.max - c.min;
  const float cells = std::clamp(8.0f * std::sqrt(float(c.triangles.size())), 16.0f, 512.0f);
  const float cell = std::max(extent.x, extent.y) / cells;
  if (!(cell > 0.0f)) return false;
  const int w = int(extent.x / cell) + 1, h = int(extent.y / cell) + 1;
  std::vector<int> owner(std::size_t(w) * h, -1);
  for (int t : c.triangles) {
    glm::vec2 q[3];
    for (int k = 0; k < 3; ++k) q[k] = (project(mesh.positions[mesh.triangles[t][k]], c.axis) - c.min) / cell;
    const float area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
    if (std::abs(area) < 1e-12f) continue;
    const glm::vec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
    for (int y = std::max(0, int(lo.y)); y <= std::min(h - 1, int(hi.y)); ++y)
      for (int x = std::max(0, int(lo.x)); x <= std::min(w - 1, int(hi.x)); ++x) {
        const glm::vec2 p(x + 0.5f, y + 0.5f);
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          const glm::vec2 a = q[k], b = q[(k + 1) % 3];
          // Strictly inside (by a margin), so neighbours sharing an edge never both claim a cell.
          inside =
              ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area > 1e-4f * glm::length(b - a);
        }
        if (!inside) continue;
        int& o = owner[std::size_t(y) * w + x];
        if (o >= 0 && o != t) return true;
        o = t;
      }
  }
  return false;
}

// Texel size of a chart's rectangle (with the gutter) at `texelsPerMm`.
glm::ivec2 rectSize(const ChartShape& c, float texelsPerMm, int padding) {
  const glm::vec2 e = (c.max - c.min) * texelsPerMm;
  return glm::ivec2(int(std::ceil(e.x)) + 1 + 2 * padding, int(std::ceil(e.y)) + 1 + 2 * padding);
}

// Shelf packing in the order given; false when the square is too small.
bool shelfPack(const std::vector<ChartShape>& charts, const std::vector<int>& order, float texelsPerMm,
               int padding, int side, std::vector<glm::ivec2>* origins) {
  int x = 0, y = 0, shelfHeight = 0;
  if (origins) origins->assign(charts.size(), glm::ivec2(0));
  for (int i : order) {
    const glm::ivec2 s = rectSize(charts[i], texelsPerMm, padding);
    if (s.x > side) return false;
    if (x + s.x > side) {
      y += shelfHeight;
      x = 0;
      shelfHeight = 0;
    }
    if (y + s.y > side) return false;
    if (origins) (*origins)[i] = glm::ivec2(x, y);
    x += s.x;
    shelfHeight = std::max(shelfHeight, s.y);
  }
  return true;
}

}  // namespace

UvAtlas buildUvAtlas(const Mesh& mesh, const UvAtlasOptions& options) {
  if (options.resolution < 16 || options.resolution > 16384)
    throw InputError("the texture resolution must be between 16 and 16384 texels");
  if (mesh.triangles.empty()) throw InputError("mesh " + mesh.name + " has no faces");
  const int side = options.resolution;
  checkImageSize({side, side}, "the part's texture");
  const int padding = options.padding >= 0 ? options.padding : std::max(2, side / 256);
  const std::size_t triangleCount = mesh.triangles.size();

  // Triangles: axis class, then union across shared edges of the same class.
  const std::vector<int> welded = weldByPosition(mesh.positions);
  std::vector<int> axisOf(triangleCount);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const glm::uvec3 tri = mesh.triangles[t];
    const glm::vec3 n = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                                   mesh.positions[tri.z] - mesh.positions[tri.x]);
    axisOf[t] = dominantAxis(n);
  }
  UnionFind sets(triangleCount);
  std::unordered_map<std::uint64_t, int> firstTriangleOfEdge;  // (edge, axis) -> a triangle
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const glm::uvec3 tri = mesh.triangles[t];
    for (int e = 0; e < 3; ++e) {
      std::uint64_t a = welded[tri[e]], b = welded[tri[(e + 1) % 3]];
      if (a > b) std::swap(a, b);
      const std::uint64_t key = ((a << 29 | b) << 3) | std::uint64_t(axisOf[t]);
      const auto [it, inserted] = firstTriangleOfEdge.emplace(key, int(t));
      if (!inserted) sets.join(int(t), it->second);
    }
  }
  // Connected pieces; a piece whose projection folds onto itself becomes one chart per triangle.
  std::vector<std::vector<int>> pieces;
  std::unordered_map<int, int> pieceOfRoot;
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const auto [it, inserted] = pieceOfRoot.emplace(sets.find(int(t)), int(pieces.size()));
    if (inserted) pieces.emplace_back();
    pieces[it->second].push_back(int(t));
  }
  std::vector<ChartShape> charts;
  for (const std::vector<int>& piece : pieces) {
    ChartShape whole = chartOf(mesh, piece, axisOf[piece.front()]);
    if (!projectionOverlaps(mesh, whole)) {
      charts.push_back(std::move(whole));
      continue;
    }
    for (int t : piece) charts.push_back(chartOf(mesh, {t}, whole.axis));
  }
  std::vector<int> chartOfTriangle(triangleCount);
  for (std::size_t c = 0; c < charts.size(); ++c)
    for (int t : charts[c].triangles) chartOfTriangle[t] = int(c);

  // The largest texels per mm whose shelf packing fits, by bisection.
  std::vector<int> order(charts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return charts[a].max.y - charts[a].min.y > charts[b].max.y - charts[b].min.y;
  });
  float largestExtent = 1e-6f;
  for (const ChartShape& c : charts)
    largestExtent = std::max({largestExtent, c.max.x - c.min.x, c.max.y - c.min.y});
  float low = 0.0f, high = float(side) / largestExtent;
  if (!shelfPack(charts, order, 1e-9f, padding, side, nullptr))
    throw InputError("mesh " + mesh.name + " has " + std::to_string(charts.size()) +
                     " separate pieces, too many for a " + std::to_string(side) +
                     " px texture; raise the texture resolution");
  if (options.maxTexelsPerMm > 0.0f &&
      shelfPack(charts, order, options.maxTexelsPerMm, padding, side, nullptr)) {
    low = options.maxTexelsPerMm;
  } else {
    for (int i = 0; i < 40; ++i) {
      const float mid = 0.5f * (low + high);
      (shelfPack(charts, order, mid, padding, side, nullptr) ? low : high) = mid;
    }
  }
  std::vector<glm::ivec2> origins;
  shelfPack(charts, order, low, padding, side, &origins);

  UvAtlas atlas;
  atlas.resolution = side;
  atlas.padding = padding;
  atlas.texelsPerMm = low;
  atlas.chartOfTriangle = chartOfTriangle;
  atlas.mesh.name = mesh.name;
  atlas.mesh.triangles.resize(triangleCount);
  const bool normals = mesh.hasNormals();
  for (std::size_t ci = 0; ci < charts.size(); ++ci) {
    const ChartShape& c = charts[ci];
    const glm::ivec2 size = rectSize(c, low, padding);
    atlas.charts.push_back({c.axis, origins[ci].x, origins[ci].y, size.x, size.y});
    // Vertices shared inside a chart stay shared; each chart has its own copies.
    std::unordered_map<unsigned, unsigned> local;
    for (int t : c.triangles) {
      for (int k = 0; k < 3; ++k) {
        const unsigned source = mesh.triangles[t][k];
        auto [it, inserted] = local.emplace(source, unsigned(atlas.mesh.positions.size()));
        if (inserted) {
          const glm::vec3 p = mesh.positions[source];
          // Texel coordinates: the chart's corner + gutter + half a texel, so the chart's edge texels
          // have their centres on the surface.
          const glm::vec2 texel =
              glm::vec2(origins[ci] + padding) + 0.5f + (project(p, c.axis) - c.min) * low;
          atlas.mesh.positions.push_back(p);
          if (normals) atlas.mesh.normals.push_back(mesh.normals[source]);
          atlas.mesh.uvs.push_back(texel / float(side));
          atlas.sourceVertex.push_back(int(source));
        }
        atlas.mesh.triangles[t][k] = it->second;
      }
    }
  }
  return atlas;
}

}  // namespace kerf
