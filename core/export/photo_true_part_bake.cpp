#include "export/photo_true_part_bake.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/texel_guidance.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr int kMaxSynthesisSide = 16384;
constexpr std::uint32_t kPartSalt = 0x9A27u;  // one seed for a part's atlas (mixed with model.seed)

// An atlas of the same charts at the photos' texels per mm: the resolution is raised until it fits.
UvAtlas synthesisAtlas(const Mesh& placed, const UvAtlas& part, float pxPerMm, int padding) {
  UvAtlasOptions options;
  options.padding = padding;
  options.maxTexelsPerMm = pxPerMm;
  double side = std::ceil(part.resolution * pxPerMm / part.texelsPerMm * 1.05) + 4 * padding;
  for (int attempt = 0; attempt < 8; ++attempt) {
    options.resolution = static_cast<int>(std::clamp(side, 16.0, double(kMaxSynthesisSide)));
    UvAtlas atlas = buildUvAtlas(placed, options);
    if (atlas.texelsPerMm >= pxPerMm * 0.999f) return atlas;
    if (options.resolution == kMaxSynthesisSide) break;
    side = std::ceil(options.resolution * std::max(1.05, pxPerMm / atlas.texelsPerMm * 1.02));
  }
  std::ostringstream s;
  s.precision(3);
  s << "the part's surface is too large for a photo-true texture: at the photos' " << pxPerMm
    << " px/mm its charts do not fit " << kMaxSynthesisSide << " x " << kMaxSynthesisSide << " texels";
  throw InputError(s.str());
}

// Per triangle: block mm per texel step right and down (the affine map from texels to the triangle).
void triangleFrame(const UvAtlas& atlas, int t, glm::vec3& right, glm::vec3& down) {
  const glm::uvec3 c = atlas.mesh.triangles[t];
  const float side = float(atlas.resolution);
  const glm::vec2 u1 = (atlas.mesh.uvs[c.y] - atlas.mesh.uvs[c.x]) * side;
  const glm::vec2 u2 = (atlas.mesh.uvs[c.z] - atlas.mesh.uvs[c.x]) * side;
  const glm::vec3 e1 = atlas.mesh.positions[c.y] - atlas.mesh.positions[c.x];
  const glm::vec3 e2 = atlas.mesh.positions[c.z] - atlas.mesh.positions[c.x];
  const float det = u1.x * u2.y - u2.x * u1.y;
  if (std::abs(det) < 1e-12f) {
    right = down = glm::vec3(0.0f);
    return;
  }
  right = (e1 * u2.y - e2 * u1.y) / det;
  down = (e2 * u1.x - e1 * u2.x) / det;
}

// The synthesis atlas' used rectangle (shelves leave the rest empty) as texels with points and frames.
TexelSurface texelSurface(const UvAtlas& atlas) {
  TexelSurface s;
  for (const UvAtlas::Chart& c : atlas.charts) {
    s.width = std::max(s.width, c.x + c.width);
    s.height = std::max(s.height, c.y + c.height);
  }
  s.width = std::min(s.width, atlas.resolution);
  s.height = std::min(s.height, atlas.resolution);
  const std::size_t n = static_cast<std::size_t>(s.width) * s.height;
  s.point.assign(n, glm::vec3(0.0f));
  s.right.assign(n, glm::vec3(0.0f));
  s.down.assign(n, glm::vec3(0.0f));
  s.region.assign(n, -1);
  const std::vector<int> owner = atlasTexelOwners(atlas);
  std::vector<glm::vec3> rights(atlas.mesh.triangles.size()), downs(atlas.mesh.triangles.size());
  for (int t = 0; t < int(atlas.mesh.triangles.size()); ++t) triangleFrame(atlas, t, rights[t], downs[t]);
  parallelRows(s.height, [&](int y) {
    for (int x = 0; x < s.width; ++x) {
      const int t = owner[std::size_t(y) * atlas.resolution + x];
      if (t < 0) continue;
      const std::size_t i = std::size_t(y) * s.width + x;
      const glm::vec3 w = atlasBarycentric(atlas, t, glm::vec2(x + 0.5f, y + 0.5f));
      const glm::uvec3 c = atlas.mesh.triangles[t];
      s.point[i] =
          w.x * atlas.mesh.positions[c.x] + w.y * atlas.mesh.positions[c.y] + w.z * atlas.mesh.positions[c.z];
      s.right[i] = rights[t];
      s.down[i] = downs[t];
      s.region[i] = atlas.chartOfTriangle[t];
    }
  });
  return s;
}

glm::vec3 bilinear(const Image& image, glm::vec2 p) {
  const float x = std::clamp(p.x, 0.0f, image.width - 1.0f), y = std::clamp(p.y, 0.0f, image.height - 1.0f);
  const int x0 = std::min(static_cast<int>(x), std::max(image.width - 2, 0));
  const int y0 = std::min(static_cast<int>(y), std::max(image.height - 2, 0));
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float fx = x - x0, fy = y - y0;
  const auto at = [&](int px, int py) {
    const float* v = image.pixel(px, py);
    return glm::vec3(v[0], v[1], v[2]);
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) +
         fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

}  // namespace

BakedTexture bakePhotoTruePart(const PhotoTrueAppearance& appearance, const WoodModel& model,
                               const Mesh& placedMesh, const UvAtlas& atlas, int samples,
                               const Progress& progress) {
  // A gutter as wide as a patch reaches, so that a patch at a chart's edge sees that chart continued
  // (the guidance's gutter fill) rather than its neighbour in the atlas.
  const int padding = appearance.options().synthesis.patchRadius + 1;
  const UvAtlas synth = synthesisAtlas(placedMesh, atlas, appearance.synthesisPxPerMm(), padding);
  progress.throwIfCancelled();
  const TexelSurface surface = texelSurface(synth);
  const SurfaceGuidance guidance =
      computeTexelGuidance(model, surface, appearance.options().weights, progress.part(0.0, 0.1));
  const Image synthesised = appearance.renderGuidance(guidance, kPartSalt, progress.part(0.1, 0.9));
  // Onto the part's atlas through each triangle: a point's texel in the synthesis atlas from its
  // barycentric coordinates there (the triangles are the same, in the same order).
  const float side = float(synth.resolution);
  return bakeAtlasTexture(
      atlas,
      [&](int t, glm::vec3 w) {
        const glm::uvec3 c = synth.mesh.triangles[t];
        const glm::vec2 texel =
            (w.x * synth.mesh.uvs[c.x] + w.y * synth.mesh.uvs[c.y] + w.z * synth.mesh.uvs[c.z]) * side;
        return bilinear(synthesised, texel - 0.5f);
      },
      samples, progress.part(0.9, 1.0));
}

}  // namespace kerf
