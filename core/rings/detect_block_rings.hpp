#pragma once
// Ring localization on every face photo of a block (Mokume Sec. 5.1): the one per-face loop behind
// `kerf-cli detect`, `kerf-cli fit` / `reconstruct` on photos alone, and the editor's Detect Rings.
// Each photo is localized at the resolution the block gives it (photo pixels per face millimetre) and
// its contours are extracted as the Mokume authors do (rings/contours.hpp).
#include <array>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/block.hpp"
#include "geometry/face_set.hpp"
#include "io/image.hpp"
#include "rings/contours.hpp"
#include "rings/ring_detector.hpp"
#include "util/progress.hpp"

namespace kerf {

struct DetectedFaceRings {
  Image arl;                          // the ring-localization image, 1 channel in [0, 1], the photo's size
  std::vector<FaceContour> contours;  // extracted from arl (pixel indices)
  glm::vec2 pxPerMm{0.0f};            // photo pixels per face mm along its width and height
  double seconds = 0;                 // detection time of this face
  float meanPxPerMm() const { return 0.5f * (pxPerMm.x + pxPerMm.y); }
  // Whether the photo's pixels are square on the wood (within 3 %); the detector assumes it.
  bool squarePixels() const;
};

struct BlockRingDetection {
  std::array<std::optional<DetectedFaceRings>, 6> faces;  // A..F; none: no photo, or held out
  int faceCount() const;
  int contourCount() const;
  std::string countsText() const;  // "A:10 B:19 ..", the detected faces only
};

// Detects the rings on each face photo (A..F; empty photos are skipped) except the held-out faces (their
// photos are used by nothing: fit/held_out_faces.hpp). Progress is shared evenly among the faces.
// InputError when no photo is left to detect on; Cancelled on request.
BlockRingDetection detectBlockRings(const std::array<Image, 6>& photos, const Block& block,
                                    const FaceSet& heldOut = {}, const Progress& progress = {},
                                    const RingDetector& detector = ClassicalRingDetector());

}  // namespace kerf
