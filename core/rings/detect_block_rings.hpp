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
#include "image/image.hpp"
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

// The largest face photo ring detection takes (issue 21: six 120-megapixel grey faces kept detect busy for
// minutes). The detector's filters are sized in mm on the wood, so their cost per pixel grows with the
// resolution: six faces took 2.8 s at 512 px, 19 s at 1024 px and 143 s at 2048 px a side (Release, the
// shared 2-core machine of docs/reliability.md). 2 megapixels a face keeps six faces to about a minute
// there; Mokume's faces are 256 px.
inline constexpr long long kMaxRingDetectionPixels = 2'000'000;
// The ring detector's own minimum (its filters need a few pixels each way).
inline constexpr int kMinRingDetectionSide = 4;
// Throws InputError naming `what` (a photo's file, or "the photo of face A"), its size and the bound
// unless a width x height photo is within kMaxRingDetectionPixels and kMinRingDetectionSide a side.
void checkRingDetectionSize(int width, int height, const std::string& what);

// Detects the rings on each face photo (A..F; empty photos are skipped) except the held-out faces (their
// photos are used by nothing: fit/held_out_faces.hpp). Progress is shared evenly among the faces.
// InputError when no photo is left to detect on or one is over kMaxRingDetectionPixels (checked for every
// face before any is detected); Cancelled on request.
BlockRingDetection detectBlockRings(const std::array<Image, 6>& photos, const Block& block,
                                    const FaceSet& heldOut = {}, const Progress& progress = {},
                                    const RingDetector& detector = ClassicalRingDetector());

}  // namespace kerf
