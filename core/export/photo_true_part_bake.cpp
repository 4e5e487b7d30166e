#include "export/photo_true_part_bake.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/texel_guidance.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

constexpr int kMaxSynthesisSide = 16384;
constexpr std::uint32_t kPartSalt = 0x9A27u;  // one seed for a part's atlas (mixed with model.seed)

// An atlas of the same charts at the photos' texels per mm: its side raised until they fit at that scale
// (only the charts' rectangles are synthesised, so the side need not be the smallest).
UvAtlas synthesisAtlas(const Mesh& placed, const UvAtlas& part, float pxPerMm, int padding) {
  UvAtlasOptions options;
  options.padding = padding;
  options.maxTexelsPerMm = pxPerMm;
  double side = std::ceil(part.resolution * pxPerMm / part.texelsPerMm * 1.05) + 4.0 * padding;
  for (;;) {
    options.resolution = static_cast<int>(std::clamp(side, 16.0, double(kMaxSynthesisSide)));
    try {
      UvAtlas atlas = buildUvAtlas(placed, options);
      if (atlas.texelsPerMm >= pxPerMm * 0.999f) return atlas;
    } catch (const InputError&) {  // too many pieces for this side: a larger one may do
    }
    if (options.resolution == kMaxSynthesisSide) break;
    side = options.resolution * 1.25 + 1.0;
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

SurfaceGuidance crop(const SurfaceGuidance& g, int x0, int y0, int w, int h) {
  SurfaceGuidance out;
  out.width = w;
  out.height = h;
  for (int y = y0; y < y0 + h; ++y) {
    const std::size_t row = std::size_t(y) * g.width + x0;
    out.features.insert(out.features.end(), g.features.begin() + row * kGuidanceChannels,
                        g.features.begin() + (row + w) * kGuidanceChannels);
    out.grainAngle.insert(out.grainAngle.end(), g.grainAngle.begin() + row, g.grainAngle.begin() + row + w);
    out.inside.insert(out.inside.end(), g.inside.begin() + row, g.inside.begin() + row + w);
  }
  return out;
}

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
};

// Large charts' rectangles (with their gutters) are synthesised each on its own, with its own seed: the
// charts are islands anyway, and the shelves' empty space, which would cost as much as wood, is left out.
// The small ones (a synthesis has a fixed cost of about a 64 x 64 target) together in the rectangle around
// them all: the packing sorts charts by height, so they share the last shelves.
std::vector<Rect> synthesisRects(const UvAtlas& atlas, int width, int height) {
  constexpr int kOwnSynthesis = 64 * 64;
  std::vector<Rect> rects(1, Rect{width, height, 0, 0});  // [0]: around the small charts (empty: none)
  int x1 = 0, y1 = 0;
  for (const UvAtlas::Chart& c : atlas.charts) {
    const Rect r{c.x, c.y, std::min(c.width, width - c.x), std::min(c.height, height - c.y)};
    if (r.w <= 0 || r.h <= 0) continue;
    if (r.w * r.h >= kOwnSynthesis) {
      rects.push_back(r);
      continue;
    }
    rects[0].x = std::min(rects[0].x, r.x), rects[0].y = std::min(rects[0].y, r.y);
    x1 = std::max(x1, r.x + r.w), y1 = std::max(y1, r.y + r.h);
  }
  rects[0].w = std::max(0, x1 - rects[0].x), rects[0].h = std::max(0, y1 - rects[0].y);
  return rects;
}

// The rectangles synthesised in order (a large chart over the small charts' rectangle where they overlap).
Image synthesiseCharts(const PhotoTrueAppearance& appearance, const UvAtlas& atlas, const SurfaceGuidance& g,
                       const Progress& progress) {
  Image out(g.width, g.height, 3);
  const std::vector<Rect> rects = synthesisRects(atlas, g.width, g.height);
  double total = 0, done = 0;
  for (const Rect& r : rects) total += double(r.w) * r.h;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const Rect& r = rects[i];
    if (r.w <= 0 || r.h <= 0) continue;
    const double area = double(r.w) * r.h;
    const Image chart =
        appearance.renderGuidance(crop(g, r.x, r.y, r.w, r.h), kPartSalt + 0x9E3779B9u * std::uint32_t(i),
                                  progress.part(done / total, (done + area) / total));
    done += area;
    for (int y = 0; y < r.h; ++y) std::copy_n(chart.pixel(0, y), 3 * r.w, out.pixel(r.x, r.y + y));
  }
  return out;
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
  // Per texel of the synthesis atlas: point, frame, region, guidance, grain tensor and colour (about 120
  // bytes), refused at once rather than failing late.
  checkMemoryNeed(std::uint64_t(synth.resolution) * synth.resolution * 120, "the part's photo-true texture");
  const TexelSurface surface = texelSurface(synth);
  const SurfaceGuidance guidance =
      computeTexelGuidance(model, surface, appearance.options().weights, progress.part(0.0, 0.1));
  const Image synthesised = synthesiseCharts(appearance, synth, guidance, progress.part(0.1, 0.9));
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
