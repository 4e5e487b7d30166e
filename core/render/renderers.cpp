#include "render/renderers.hpp"

#include <cmath>
#include <string>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

void checkSamples(int samples) {
  if (samples < 1 || samples > 8) throw InputError("samples per pixel side must be 1..8");
}

}  // namespace

Image renderFace(const WoodModel& model, FaceId face, glm::ivec2 size, int samples,
                 const Progress& progress) {
  checkSamples(samples);
  checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)));
  Image image(size.x, size.y, 3);
  const float weight = 1.0f / (samples * samples);
  parallelRows(
      size.y,
      [&](int y) {
        for (int x = 0; x < size.x; ++x) {
          glm::vec3 sum(0.0f);
          for (int sy = 0; sy < samples; ++sy)
            for (int sx = 0; sx < samples; ++sx) {
              const glm::vec2 pos(x + (sx + 0.5f) / samples, y + (sy + 0.5f) / samples);
              sum += model.evaluate(model.block().imageToBlock(face, pos, size), faceIndex(face)).color;
            }
          float* out = image.pixel(x, y);
          out[0] = sum.x * weight, out[1] = sum.y * weight, out[2] = sum.z * weight;
        }
      },
      progress);
  return image;
}

std::array<Image, 6> renderFaces(const WoodModel& model, float pxPerMm, int samples,
                                 const Progress& progress) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  std::uint64_t bytes = 0;  // all six are kept
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size = model.block().faceImageSize(face, pxPerMm);
    checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)), pxPerMm);
    bytes += std::uint64_t(size.x) * std::uint64_t(size.y) * 3 * sizeof(float);
  }
  checkMemoryNeed(bytes, "rendering the six faces");
  std::array<Image, 6> images;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    Progress part{progress.report ? [&, i](double f) { progress.report((i + f) / 6.0); }
                                  : std::function<void(double)>{},
                  progress.stop};
    images[i] = renderFace(model, face, model.block().faceImageSize(face, pxPerMm), samples, part);
  }
  return images;
}

Image renderCut(const WoodModel& model, const CutPlane& plane, float pxPerMm, int samples,
                const Progress& progress) {
  checkSamples(samples);
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  const auto bounds = plane.boundsInBlock(model.block());
  if (!bounds) throw InputError("the cut plane does not pass through the block");
  const glm::vec2 extent = bounds->max - bounds->min;
  const int width = pixelsAlong(std::ceil(double(extent.x) * pxPerMm - 1e-3));
  const int height = pixelsAlong(std::ceil(double(extent.y) * pxPerMm - 1e-3));
  checkImageSize({width, height}, "the image of the cut", pxPerMm);
  Image image(width, height, 4);
  const float weight = 1.0f / (samples * samples);
  const Block& block = model.block();
  parallelRows(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          glm::vec3 sum(0.0f);
          int inside = 0;
          for (int sy = 0; sy < samples; ++sy)
            for (int sx = 0; sx < samples; ++sx) {
              // Image right = plane right, image down = plane -up; the top-left pixel is at (min.x, max.y).
              const glm::vec2 planePos(bounds->min.x + (x + (sx + 0.5f) / samples) / pxPerMm,
                                       bounds->max.y - (y + (sy + 0.5f) / samples) / pxPerMm);
              const glm::vec3 p = plane.toBlock(planePos);
              if (!block.contains(p)) continue;
              sum += model.evaluate(p).color;
              ++inside;
            }
          float* out = image.pixel(x, y);
          if (inside > 0) {
            const glm::vec3 c = sum / float(inside);
            out[0] = c.x, out[1] = c.y, out[2] = c.z;
          }
          out[3] = inside * weight;
        }
      },
      progress);
  return image;
}

}  // namespace kerf
