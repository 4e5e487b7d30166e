#pragma once
// An anatomical prior on the pith direction: the fibre (grain) direction of the block, estimated from the
// texture orientation of the six face photographs.
//
// Why: the pith runs along the stem, and so do the fibres and vessels. The ring contours alone can leave
// the pith direction badly determined (Mokume, mokume-dataset-inverse-modeling-2025, Sec. 5.2.3 fits the
// axis from the contours only; Appendix B.1 discusses the flip ambiguity), and on CN03 the authors' fit
// puts the axis along x although the anatomy says y (shared/reference/MOKUME_CONVENTIONS.md section E).
// The anatomy used here (wood-anatomy textbook facts, and what MOKUME_CONVENTIONS E reports for CN03's
// photos): on a side-grain face the vessels are cut lengthwise and show as streaks along the fibre direction
// projected on the face; on an end-grain face they are cut across and show as dots (isotropic texture at pore
// scale).
//
// Method (details in anatomy_prior.cpp):
//  1. Per face: luminance -> log (so uneven light and colour scale drop out) -> band-pass at pore scale
//     (difference of Gaussians: fine detail kept, rings, figure and lighting removed) -> structure tensor
//     (gradient outer products smoothed over a few pixels) -> per-pixel orientation and coherence ->
//     the coherence-weighted mean of the doubled-angle orientation vectors over the face. Its length is
//     the face's anisotropy (0: isotropic, like end grain; 1: every pixel streaked the same way), its angle
//     the streak direction, mapped to a 3D direction in the face plane with the face frame (block.hpp).
//  2. Combination: a 3x3 orientation tensor M = sum_f a_f s_f s_f^T over the faces (s_f the streak
//     direction, a_f the anisotropy) plus, for faces much less anisotropic than the most anisotropic one,
//     an end-grain vote endGrainWeight * (a_max - a_f) n_f n_f^T along the face normal. The fibre
//     direction F is M's leading eigenvector; confidence = (l1 - l2) / (l1 + l2 + l3) in [0, 1].
//  3. A candidate pith direction V is scored by penalty(V) = confidence * (1 - (V.F)^2) (0 along F,
//     `confidence` across it).
#include <array>
#include <glm/vec3.hpp>

#include "geometry/block.hpp"
#include "io/image.hpp"

namespace kerf {

struct AnatomyOptions {
  float fineSigmaPx = 0.7f;    // band-pass: inner Gaussian (noise), pixels
  float coarseSigmaPx = 4.0f;  // band-pass: outer Gaussian (rings, lighting), pixels
  float tensorSigmaPx = 2.0f;  // structure tensor integration scale, pixels
  float endGrainWeight = 0.5f;
  int borderPx = 4;  // pixels ignored along the image edges
};

struct FaceAnatomy {
  bool present = false;
  float anisotropy = 0;      // 0..1
  float streakAngleDeg = 0;  // in the image: 0 = along columns (+x), 90 = along rows (down)
  glm::vec3 streak{0};       // the streak direction in the block frame (unit, sign arbitrary)
};

struct AnatomyEstimate {
  glm::vec3 fibre{0, 1, 0};                   // unit, turned to +y (sign is meaningless)
  float confidence = 0;                       // 0..1
  std::array<float, 3> eigenvalues{0, 0, 0};  // of M, descending
  std::array<FaceAnatomy, 6> faces;
  int facesUsed = 0;
};

// Texture orientation of one face image (RGB or grey, values 0..1).
FaceAnatomy analyzeFaceTexture(const Image& image, const Block& block, FaceId face,
                               const AnatomyOptions& options = {});

// From the six face photos (A..F order; empty images are skipped). Throws InputError with no usable face.
AnatomyEstimate estimateFibreDirection(const std::array<Image, 6>& photos, const Block& block,
                                       const AnatomyOptions& options = {});

// confidence * (1 - (V.F)^2) for a candidate pith direction V (need not be unit).
double anatomyPenalty(const AnatomyEstimate& estimate, glm::vec3 direction);

// Angle between V and the fibre direction, 0..90 degrees (the sign of V is ignored).
double anatomyAngleDeg(const AnatomyEstimate& estimate, glm::vec3 direction);

}  // namespace kerf
