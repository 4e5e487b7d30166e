#include "texture/face_crops.hpp"
#include "util/split_mix.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "render/wood_model.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

constexpr int kEdgeMarginPx = 3;

}  // namespace

FaceCropLayout placeFaceCrops(const Block& block, const std::array<Image, 6>& photos, int perFace, int size,
                              std::uint32_t seed) {
  if (perFace < 1 || size < 8) throw InputError("texture crops: at least one crop of 8 px per face");
  FaceCropLayout layout;
  SplitMix random{seed * 0x2545F4914F6CDD1DULL + 1};
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    const Image& photo = photos[i];
    if (photo.empty()) continue;
    const FaceFrame frame = block.face(face);
    const float pxPerMm = photo.width / frame.widthMm;
    const float expectedHeight = frame.heightMm * pxPerMm;
    if (std::abs(photo.height - expectedHeight) > 0.02f * expectedHeight + 1.0f) {
      throw InputError("the photo of face " + std::string(1, faceLetter(face)) + " is " +
                       std::to_string(photo.width) + " x " + std::to_string(photo.height) +
                       " px, but the face is " + std::to_string(frame.widthMm) + " x " +
                       std::to_string(frame.heightMm) + " mm: its proportions differ from the face's");
    }
    layout.imageSize[i] = {photo.width, photo.height};
    layout.pxPerMm[i] = pxPerMm;
    const int w = std::min(size, photo.width - 2 * kEdgeMarginPx);
    const int h = std::min(size, photo.height - 2 * kEdgeMarginPx);
    if (w < 8 || h < 8)
      throw InputError("the photo of face " + std::string(1, faceLetter(face)) + " is too small");
    for (int k = 0; k < perFace; ++k) {
      FaceCrop crop{face, kEdgeMarginPx + random.below(photo.width - 2 * kEdgeMarginPx - w + 1),
                    kEdgeMarginPx + random.below(photo.height - 2 * kEdgeMarginPx - h + 1), w, h};
      layout.crops.push_back(crop);
    }
  }
  if (layout.crops.empty()) throw InputError("no face photo to infer the texture from");
  return layout;
}

Image cropImage(const Image& image, const FaceCrop& crop) {
  Image out(crop.width, crop.height, 3);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      const float* p = image.pixel(crop.x + x, crop.y + y);
      float* q = out.pixel(x, y);
      q[0] = p[0], q[1] = p[1], q[2] = p[2];
    }
  return out;
}

Image renderFaceCrop(const WoodModel& model, const FaceCrop& crop, glm::ivec2 imageSize, int samples) {
  Image out(crop.width, crop.height, 3);
  const float weight = 1.0f / (samples * samples);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx) {
          const glm::vec2 pos(crop.x + x + (sx + 0.5f) / samples, crop.y + y + (sy + 0.5f) / samples);
          sum += model.evaluate(model.block().imageToBlock(crop.face, pos, imageSize), faceIndex(crop.face))
                     .color;
        }
      float* q = out.pixel(x, y);
      q[0] = sum.x * weight, q[1] = sum.y * weight, q[2] = sum.z * weight;
    }
  return out;
}

std::vector<WoodLocation> locateFaceCrop(const WoodModel& model, const FaceCrop& crop, glm::ivec2 imageSize,
                                         int samples) {
  std::vector<WoodLocation> out;
  out.reserve(static_cast<std::size_t>(crop.width) * crop.height * samples * samples);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx) {
          const glm::vec2 pos(crop.x + x + (sx + 0.5f) / samples, crop.y + y + (sy + 0.5f) / samples);
          out.push_back(model.material().locate(model.block().imageToBlock(crop.face, pos, imageSize)));
        }
  return out;
}

Image renderFaceCrop(const WoodModel& model, const FaceCrop& crop, const std::vector<WoodLocation>& located,
                     int samples) {
  if (located.size() != static_cast<std::size_t>(crop.width) * crop.height * samples * samples)
    throw std::logic_error("renderFaceCrop: the locations are not of this crop");
  Image out(crop.width, crop.height, 3);
  const float weight = 1.0f / (samples * samples);
  const int face = faceIndex(crop.face);
  const WoodLocation* at = located.data();
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int i = 0; i < samples * samples; ++i) sum += model.material().shade(*at++, face).color;
      float* q = out.pixel(x, y);
      q[0] = sum.x * weight, q[1] = sum.y * weight, q[2] = sum.z * weight;
    }
  return out;
}

FaceOrientation faceOrientation(const Block& block, FaceId face, const PithAxis& axis) {
  const FaceFrame frame = block.face(face);
  FaceOrientation out;
  const float along = std::min(1.0f, std::abs(glm::dot(frame.normal, axis.direction)));
  out.angleToPithDeg = std::acos(along) * 180.0f / std::numbers::pi_v<float>;
  if (out.angleToPithDeg < 45.0f) {
    out.grain = FaceGrain::EndGrain;
  } else {
    // Side grain: flat-sawn when the face looks along the radius (tangential to the rings), quarter-sawn
    // when it looks around the tree (the face contains the radius).
    const Cylindrical c = axis.toCylindrical(frame.center, false);
    out.grain = std::abs(glm::dot(frame.normal, c.radial)) > std::cos(std::numbers::pi_v<float> / 4)
                    ? FaceGrain::FlatSawn
                    : FaceGrain::QuarterSawn;
  }
  return out;
}

std::string faceGrainName(FaceGrain grain) {
  switch (grain) {
    case FaceGrain::EndGrain:
      return "end grain";
    case FaceGrain::FlatSawn:
      return "side grain (flat-sawn)";
    case FaceGrain::QuarterSawn:
      return "side grain (quarter-sawn)";
  }
  return "";
}

}  // namespace kerf
