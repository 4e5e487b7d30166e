#include "geometry/block.hpp"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {

char faceLetter(FaceId face) {
  return static_cast<char>('A' + faceIndex(face));
}

std::optional<FaceId> faceFromLetter(char letter) {
  if (letter >= 'a' && letter <= 'f') letter = static_cast<char>(letter - 'a' + 'A');
  if (letter < 'A' || letter > 'F') return std::nullopt;
  return static_cast<FaceId>(letter - 'A');
}

CrossSlot crossSlot(FaceId face) {
  switch (face) {
    case FaceId::A:
      return {1, 1};
    case FaceId::B:
      return {1, 0};
    case FaceId::C:
      return {0, 1};
    case FaceId::D:
      return {1, 2};
    case FaceId::E:
      return {2, 1};
    case FaceId::F:
      return {3, 1};
  }
  return {1, 1};
}

namespace {
constexpr float kMinBlockSideMm = 0.01f;
}  // namespace

Block::Block(glm::vec3 sizeMm) : size_(sizeMm) {
  for (int i = 0; i < 3; ++i) {
    // Below 0.01 mm a face image has no pixel at any resolution Kerf makes (a 1e-30 mm block made
    // OpenCV assert); above 100 m pixel counts overflow.
    if (!std::isfinite(size_[i]) || size_[i] < kMinBlockSideMm || size_[i] > kMaxBlockSideMm) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "block size must be three positive lengths of at least 0.01 mm and at most 100000 mm, "
                    "got %g x %g x %g",
                    size_.x, size_.y, size_.z);
      throw InputError(text);
    }
  }
}

bool Block::contains(glm::vec3 p, float tol) const {
  const glm::vec3 h = halfSize() + tol;
  return std::abs(p.x) <= h.x && std::abs(p.y) <= h.y && std::abs(p.z) <= h.z;
}

FaceFrame Block::face(FaceId face) const {
  const glm::vec3 h = halfSize();
  const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  // The Mokume table (MOKUME_CONVENTIONS.md A): image right / image down per face.
  switch (face) {
    case FaceId::A:
      return {Z * h.z, X, -Y, Z, size_.x, size_.y};
    case FaceId::B:
      return {Y * h.y, X, Z, Y, size_.x, size_.z};
    case FaceId::C:
      return {-X * h.x, Z, -Y, -X, size_.z, size_.y};
    case FaceId::D:
      return {-Y * h.y, X, -Z, -Y, size_.x, size_.z};
    case FaceId::E:
      return {X * h.x, -Z, -Y, X, size_.z, size_.y};
    case FaceId::F:
      return {-Z * h.z, -X, -Y, -Z, size_.x, size_.y};
  }
  return {};
}

glm::ivec2 Block::faceImageSize(FaceId id, float pxPerMm) const {
  const FaceFrame f = face(id);
  return {pixelsAlong(std::round(double(f.widthMm) * pxPerMm)),
          pixelsAlong(std::round(double(f.heightMm) * pxPerMm))};
}

glm::vec3 Block::imageToBlock(FaceId id, glm::vec2 pos, glm::ivec2 imageSize) const {
  const FaceFrame f = face(id);
  const float u = (pos.x / imageSize.x - 0.5f) * f.widthMm;
  const float v = (pos.y / imageSize.y - 0.5f) * f.heightMm;
  return f.center + u * f.right + v * f.down;
}

glm::vec2 Block::blockToImage(FaceId id, glm::vec3 p, glm::ivec2 imageSize) const {
  const FaceFrame f = face(id);
  const glm::vec3 d = p - f.center;
  return {(glm::dot(d, f.right) / f.widthMm + 0.5f) * imageSize.x,
          (glm::dot(d, f.down) / f.heightMm + 0.5f) * imageSize.y};
}

}  // namespace kerf
