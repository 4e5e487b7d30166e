#include "mesh/bake_part_texture.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

// How far outside a triangle (in texels) a texel centre may lie and still be evaluated on it: half the
// diagonal, so every texel whose square touches the triangle is covered.
constexpr float kRimTexels = 0.7072f;

struct TexelTriangle {
  glm::vec2 a, b, c;  // texel coordinates of the corners
  float area2 = 0;    // twice the signed area
};

TexelTriangle texelTriangle(const UvAtlas& atlas, int t) {
  const glm::uvec3 tri = atlas.mesh.triangles[t];
  const float side = float(atlas.resolution);
  TexelTriangle r{atlas.mesh.uvs[tri.x] * side, atlas.mesh.uvs[tri.y] * side, atlas.mesh.uvs[tri.z] * side};
  r.area2 = (r.b.x - r.a.x) * (r.c.y - r.a.y) - (r.c.x - r.a.x) * (r.b.y - r.a.y);
  return r;
}

// Barycentric coordinates of q (may be negative outside).
glm::vec3 barycentric(const TexelTriangle& t, glm::vec2 q) {
  const auto edge = [](glm::vec2 p0, glm::vec2 p1, glm::vec2 x) {
    return (p1.x - p0.x) * (x.y - p0.y) - (x.x - p0.x) * (p1.y - p0.y);
  };
  return glm::vec3(edge(t.b, t.c, q), edge(t.c, t.a, q), edge(t.a, t.b, q)) / t.area2;
}

// Distance in texels of q outside the triangle's edges (<= 0 inside), from the barycentrics.
float outsideDistance(const TexelTriangle& t, glm::vec3 w) {
  const float lengths[3] = {glm::length(t.c - t.b), glm::length(t.a - t.c), glm::length(t.b - t.a)};
  float worst = -INFINITY;
  for (int i = 0; i < 3; ++i)
    worst = std::max(worst, -w[i] * std::abs(t.area2) / std::max(lengths[i], 1e-12f));
  return worst;
}

// Marks the texels each triangle owns: first texels whose centre is inside (rim = false), then the rim.
void rasterize(const UvAtlas& atlas, bool rim, std::vector<int>& owner) {
  const int side = atlas.resolution;
  for (int t = 0; t < int(atlas.mesh.triangles.size()); ++t) {
    const TexelTriangle tri = texelTriangle(atlas, t);
    if (std::abs(tri.area2) < 1e-12f) continue;
    const float grow = rim ? 1.0f : 0.0f;
    const glm::vec2 lo = glm::min(tri.a, glm::min(tri.b, tri.c)) - grow;
    const glm::vec2 hi = glm::max(tri.a, glm::max(tri.b, tri.c)) + grow;
    const int x0 = std::max(0, int(std::floor(lo.x))), x1 = std::min(side - 1, int(std::floor(hi.x)));
    const int y0 = std::max(0, int(std::floor(lo.y))), y1 = std::min(side - 1, int(std::floor(hi.y)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        int& o = owner[std::size_t(y) * side + x];
        if (o >= 0) continue;
        const glm::vec3 w = barycentric(tri, glm::vec2(x + 0.5f, y + 0.5f));
        const bool take = rim ? outsideDistance(tri, w) <= kRimTexels : (w.x >= 0 && w.y >= 0 && w.z >= 0);
        if (take) o = t;
      }
  }
}

// Fills empty texels outwards from the filled ones, `rounds` times, then the rest with the mean colour.
void dilate(Image& image, std::vector<char>& filled, int rounds) {
  const int w = image.width, h = image.height;
  for (int round = 0; round < rounds; ++round) {
    std::vector<char> next = filled;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (filled[std::size_t(y) * w + x]) continue;
        glm::vec3 sum(0.0f);
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || !filled[std::size_t(ny) * w + nx]) continue;
            const float* p = image.pixel(nx, ny);
            sum += glm::vec3(p[0], p[1], p[2]);
            ++n;
          }
        if (n == 0) continue;
        float* out = image.pixel(x, y);
        out[0] = sum.x / n, out[1] = sum.y / n, out[2] = sum.z / n;
        next[std::size_t(y) * w + x] = 1;
      }
    filled.swap(next);
  }
  glm::dvec3 mean(0.0);
  std::size_t n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (filled[std::size_t(y) * w + x]) {
        const float* p = image.pixel(x, y);
        mean += glm::dvec3(p[0], p[1], p[2]);
        ++n;
      }
  if (n == 0) return;
  mean /= double(n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!filled[std::size_t(y) * w + x]) {
        float* out = image.pixel(x, y);
        out[0] = float(mean.x), out[1] = float(mean.y), out[2] = float(mean.z);
      }
}

}  // namespace

std::vector<int> atlasTexelOwners(const UvAtlas& atlas) {
  std::vector<int> owner(std::size_t(atlas.resolution) * atlas.resolution, -1);
  rasterize(atlas, false, owner);
  rasterize(atlas, true, owner);
  return owner;
}

glm::vec3 atlasBarycentric(const UvAtlas& atlas, int triangle, glm::vec2 texelPoint) {
  return barycentric(texelTriangle(atlas, triangle), texelPoint);
}

BakedTexture bakePartTexture(const WoodModel& model, const UvAtlas& atlas, int samples,
                             const Progress& progress) {
  return bakeAtlasTexture(
      atlas,
      [&](int t, glm::vec3 w) {
        const glm::uvec3 corners = atlas.mesh.triangles[t];
        const glm::vec3 p = w.x * atlas.mesh.positions[corners.x] + w.y * atlas.mesh.positions[corners.y] +
                            w.z * atlas.mesh.positions[corners.z];
        return model.evaluate(p).color;
      },
      samples, progress);
}

BakedTexture bakeAtlasTexture(const UvAtlas& atlas, const AtlasColour& colourAt, int samples,
                              const Progress& progress) {
  if (samples < 1 || samples > 8) throw InputError("samples per texel side must be 1 to 8");
  const int side = atlas.resolution;
  BakedTexture baked;
  baked.owner = atlasTexelOwners(atlas);
  progress.throwIfCancelled();
  progress.set(0.05);

  baked.image = Image(side, side, 3);
  parallelRows(
      side,
      [&](int y) {
        for (int x = 0; x < side; ++x) {
          const int t = baked.owner[std::size_t(y) * side + x];
          if (t < 0) continue;
          const TexelTriangle tri = texelTriangle(atlas, t);
          glm::vec3 c(0.0f);
          for (int sy = 0; sy < samples; ++sy)
            for (int sx = 0; sx < samples; ++sx)
              c += colourAt(
                  t, barycentric(tri, glm::vec2(x + (sx + 0.5f) / samples, y + (sy + 0.5f) / samples)));
          c /= float(samples * samples);
          float* out = baked.image.pixel(x, y);
          out[0] = c.x, out[1] = c.y, out[2] = c.z;
        }
      },
      progress.part(0.05, 0.95));

  std::vector<char> filled(baked.owner.size());
  for (std::size_t i = 0; i < filled.size(); ++i) {
    filled[i] = baked.owner[i] >= 0;
    baked.samples += filled[i] ? std::size_t(samples * samples) : 0;
  }
  dilate(baked.image, filled, atlas.padding + 1);
  progress.set(1.0);
  return baked;
}

}  // namespace kerf
