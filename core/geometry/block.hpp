#pragma once
// The block of wood and its six faces, in the Mokume unfolding convention
// (mokume-dataset-inverse-modeling-2025 Appendix A.1.1, Fig. 29; pixel/axis table in
// shared/reference/MOKUME_CONVENTIONS.md section A).
//
// Block frame: millimetres, origin at the block centre, the block spans [-size/2, size/2] on each axis.
// A Mokume cube is a 40 mm block whose "cube units" are this frame divided by 40.
// The principal pith direction runs along y (faces B at +y and D at -y).
//
// Face images: column c grows to the right, row r grows downward. Kerf maps the *centre* of pixel
// (c, r) to continuous image coordinates (c + 0.5, r + 0.5). The Mokume authors' code puts the pixel
// index itself at u = (c - 128)/256, i.e. at Kerf's continuous coordinate c (a pixel corner); see
// docs/coordinates.md.
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace kerf {

enum class FaceId { A = 0, B, C, D, E, F };
inline constexpr std::array<FaceId, 6> kAllFaces{FaceId::A, FaceId::B, FaceId::C,
                                                 FaceId::D, FaceId::E, FaceId::F};

char faceLetter(FaceId face);
std::optional<FaceId> faceFromLetter(char letter);  // 'A'..'F' or 'a'..'f'
inline int faceIndex(FaceId face) {
  return static_cast<int>(face);
}

// Where a face lies and how its image is laid on it.
struct FaceFrame {
  glm::vec3 center;  // centre of the face, block mm
  glm::vec3 right;   // unit vector: image +column direction
  glm::vec3 down;    // unit vector: image +row direction
  glm::vec3 normal;  // unit outward normal
  float widthMm;     // extent along `right`
  float heightMm;    // extent along `down`
};

// Where each face sits in the unfolded cross (units of face slots): B above A, D below A,
// C left of A, E right of A, F right of E.
struct CrossSlot {
  int column;
  int row;
};
CrossSlot crossSlot(FaceId face);

// The longest side a block (or a board, a log's bounding box, a panel) may have: 100 m. Longer is a typo
// or a unit mistake, and would overflow the pixel counts of its images.
inline constexpr float kMaxBlockSideMm = 100'000.0f;

class Block {
 public:
  // Throws InputError unless every side is finite and positive.
  explicit Block(glm::vec3 sizeMm = glm::vec3(40.0f));

  glm::vec3 size() const { return size_; }
  glm::vec3 halfSize() const { return size_ * 0.5f; }
  bool contains(glm::vec3 p, float toleranceMm = 1e-4f) const;

  FaceFrame face(FaceId face) const;

  // Image size in pixels of a face rendered at `pxPerMm` (rounded to whole pixels, at least 1).
  glm::ivec2 faceImageSize(FaceId face, float pxPerMm) const;

  // Continuous image coordinates (pixel centres at +0.5) of an image of imageSize pixels -> block mm.
  glm::vec3 imageToBlock(FaceId face, glm::vec2 imagePos, glm::ivec2 imageSize) const;
  // Block point (projected onto the face plane) -> continuous image coordinates.
  glm::vec2 blockToImage(FaceId face, glm::vec3 p, glm::ivec2 imageSize) const;
  // Convenience: the centre of pixel (column, row).
  glm::vec3 pixelCenter(FaceId face, int column, int row, glm::ivec2 imageSize) const {
    return imageToBlock(face, glm::vec2(column + 0.5f, row + 0.5f), imageSize);
  }

 private:
  glm::vec3 size_;
};

}  // namespace kerf
