#include "appearance/photo_true_volume.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "appearance/photo_true_appearance.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

// The fibre is evaluated every this many pixels of a slice and interpolated: it turns over millimetres.
constexpr int kFibreStep = 8;
// A fibre closer than this (cosine) to lying in the slice is followed as if at this angle: the wood of a
// pixel is then looked for at most 1 / kMinAlong slice spacings away.
constexpr float kMinAlong = 0.25f;

// The block axis the fibres run closest to, over a coarse grid of the block: the slices are stacked
// along it, so that they are end grain or close to it.
int fibreAxis(const WoodModel& model) {
  const glm::vec3 size = model.block().size();
  glm::vec3 sum(0.0f);
  constexpr int m = 6;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const glm::vec3 p = size * (glm::vec3(i, j, k) + 0.5f) / float(m) - 0.5f * size;
        sum += glm::abs(model.material().locate(p, true).fiberDirection);
      }
  return sum.x >= sum.y && sum.x >= sum.z ? 0 : (sum.y >= sum.z ? 1 : 2);
}

std::size_t voxelIndex(glm::ivec3 size, glm::ivec3 v) {
  return (static_cast<std::size_t>(v.z) * size.y + v.y) * size.x + v.x;
}

}  // namespace

glm::vec3 PhotoTrueVolume::colourAt(glm::vec3 pMm) const {
  const glm::vec3 f = glm::clamp((pMm - origin) / spacing, glm::vec3(0.0f), glm::vec3(size - 1));
  const glm::ivec3 a = glm::min(glm::ivec3(f), glm::max(size - 2, glm::ivec3(0)));
  const glm::ivec3 b = glm::min(a + 1, size - 1);
  const glm::vec3 t = f - glm::vec3(a);
  glm::vec3 out(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 v((corner & 1) ? b.x : a.x, (corner & 2) ? b.y : a.y, (corner & 4) ? b.z : a.z);
    const float w =
        ((corner & 1) ? t.x : 1 - t.x) * ((corner & 2) ? t.y : 1 - t.y) * ((corner & 4) ? t.z : 1 - t.z);
    const std::uint8_t* c = &rgb[voxelIndex(size, v) * 3];
    out += w * glm::vec3(c[0], c[1], c[2]);
  }
  return out / 255.0f;
}

PhotoTrueVolume PhotoTrueAppearance::renderVolume(glm::ivec3 samples, const Progress& progress) const {
  if (glm::any(glm::lessThan(samples, glm::ivec3(1))))
    throw InputError("a colour volume needs at least one sample along each side");
  const glm::vec3 blockSize = model_.block().size();
  PhotoTrueVolume volume;
  volume.sliceAxis = fibreAxis(model_);
  const int a = volume.sliceAxis, u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
  // Across the slices the photos' resolution (the patches are theirs); along them at most that.
  volume.size[u] = std::max(1, static_cast<int>(std::lround(blockSize[u] * pxPerMm_)));
  volume.size[v] = std::max(1, static_cast<int>(std::lround(blockSize[v] * pxPerMm_)));
  volume.size[a] =
      std::clamp(static_cast<int>(std::lround(blockSize[a] * pxPerMm_)), 1, std::max(1, samples[a]));
  volume.spacing = blockSize / glm::vec3(volume.size);
  volume.origin = -0.5f * blockSize + 0.5f * volume.spacing;
  checkImageSize({volume.size[u], volume.size[v]}, "a slice of the colour volume", pxPerMm_);
  const std::uint64_t voxels = std::uint64_t(volume.size.x) * volume.size.y * volume.size.z;
  checkMemoryNeed(voxels * 3, "the photo-true colour volume (" + std::to_string(volume.size.x) + " x " +
                                  std::to_string(volume.size.y) + " x " + std::to_string(volume.size.z) +
                                  " samples)");
  volume.rgb.assign(voxels * 3, 0);

  glm::vec3 axisU(0.0f), axisV(0.0f), axisA(0.0f);
  axisU[u] = 1, axisV[v] = 1, axisA[a] = 1;
  SurfaceGrid grid;
  grid.width = volume.size[u];
  grid.height = volume.size[v];
  grid.right = axisU * volume.spacing[u];
  grid.down = axisV * volume.spacing[v];
  grid.normal = axisA;
  const int w = grid.width, h = grid.height;
  const int fw = (w - 1) / kFibreStep + 2, fh = (h - 1) / kFibreStep + 2;
  std::vector<glm::vec3> fibre(static_cast<std::size_t>(fw) * fh);
  std::vector<glm::vec2> carry(static_cast<std::size_t>(w) * h);
  GuidedSliceSynthesis slices(exemplars_, options_.synthesis);
  const int count = volume.size[a];
  for (int k = 0; k < count; ++k) {
    progress.throwIfCancelled();
    const Progress part = progress.part(double(k) / count, double(k + 1) / count);
    grid.origin = volume.origin * (axisU + axisV) + (volume.origin[a] + k * volume.spacing[a]) * axisA;
    const SurfaceGuidance guidance = computeGuidance(model_, grid, options_.weights, part.part(0.0, 0.4));
    if (k > 0) {
      // Where each pixel's wood lay on the previous slice: back along the fibre by one slice spacing.
      parallelRows(fh, [&](int fy) {
        for (int fx = 0; fx < fw; ++fx)
          fibre[static_cast<std::size_t>(fy) * fw + fx] =
              model_.material()
                  .locate(grid.point(float(fx * kFibreStep), float(fy * kFibreStep)), true)
                  .fiberDirection;
      });
      parallelRows(h, [&](int y) {
        const int fy = y / kFibreStep;
        const float ty = float(y % kFibreStep) / kFibreStep;
        for (int x = 0; x < w; ++x) {
          const int fx = x / kFibreStep;
          const float tx = float(x % kFibreStep) / kFibreStep;
          auto at = [&](int i, int j) { return fibre[static_cast<std::size_t>(j) * fw + i]; };
          const glm::vec3 f = (1 - ty) * ((1 - tx) * at(fx, fy) + tx * at(fx + 1, fy)) +
                              ty * ((1 - tx) * at(fx, fy + 1) + tx * at(fx + 1, fy + 1));
          float along = f[a];
          if (std::abs(along) < kMinAlong) along = along < 0 ? -kMinAlong : kMinAlong;
          const float back = volume.spacing[a] / along;  // mm along f to the previous slice (negated)
          carry[static_cast<std::size_t>(y) * w + x] =
              glm::vec2(x - back * f[u] / volume.spacing[u], y - back * f[v] / volume.spacing[v]);
        }
      });
    }
    const Image slice = slices.next(guidance, carry, part.part(0.4, 1.0));
    parallelRows(h, [&](int y) {
      for (int x = 0; x < w; ++x) {
        glm::ivec3 voxel(0);
        voxel[u] = x, voxel[v] = y, voxel[a] = k;
        std::uint8_t* out = &volume.rgb[voxelIndex(volume.size, voxel) * 3];
        for (int c = 0; c < 3; ++c)
          out[c] = static_cast<std::uint8_t>(std::lround(std::clamp(slice.pixel(x, y)[c], 0.0f, 1.0f) * 255));
      }
    });
  }
  return volume;
}

}  // namespace kerf
