#include "rings/detect_block_rings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

bool DetectedFaceRings::squarePixels() const {
  return std::abs(pxPerMm.x - pxPerMm.y) <= 0.03f * std::max(pxPerMm.x, pxPerMm.y);
}

int BlockRingDetection::faceCount() const {
  return static_cast<int>(
      std::count_if(faces.begin(), faces.end(), [](const auto& f) { return f.has_value(); }));
}

int BlockRingDetection::contourCount() const {
  int n = 0;
  for (const auto& face : faces)
    if (face) n += static_cast<int>(face->contours.size());
  return n;
}

std::string BlockRingDetection::countsText() const {
  std::string text;
  for (FaceId face : kAllFaces)
    if (const auto& f = faces[faceIndex(face)])
      text +=
          std::string(text.empty() ? "" : " ") + faceLetter(face) + ":" + std::to_string(f->contours.size());
  return text;
}

void checkRingDetectionSize(int width, int height, const std::string& what) {
  if (width < kMinRingDetectionSide || height < kMinRingDetectionSide) {
    // Issue 21: a 1 x 1 face was refused without naming the face or its file.
    throw InputError(what + " is " + std::to_string(width) + " x " + std::to_string(height) +
                     " px; ring detection needs at least " + std::to_string(kMinRingDetectionSide) + " x " +
                     std::to_string(kMinRingDetectionSide) + " px (Mokume's faces are 256 px a side)");
  }
  const long long pixels = static_cast<long long>(width) * height;
  if (pixels <= kMaxRingDetectionPixels) return;
  std::ostringstream s;
  s.precision(4);
  s << what << " is " << width << " x " << height << " px (" << pixels / 1e6
    << " megapixels); ring detection takes faces of up to " << kMaxRingDetectionPixels / 1e6
    << " megapixels (its time grows faster than the pixel count): scale the photos down (Mokume's faces "
       "are 256 px a side)";
  throw InputError(s.str());
}

BlockRingDetection detectBlockRings(const std::array<Image, 6>& photos, const Block& block,
                                    const FaceSet& heldOut, const Progress& progress,
                                    const RingDetector& detector) {
  std::vector<FaceId> faces;
  for (FaceId face : kAllFaces)
    if (!heldOut.contains(face) && !photos[faceIndex(face)].empty()) faces.push_back(face);
  if (faces.empty())
    throw InputError(heldOut.empty() ? "there are no face photos to detect rings on"
                                     : "there are no face photos to detect rings on besides the held-out "
                                       "faces " +
                                           heldOut.letters());
  for (FaceId face : faces) {
    const Image& photo = photos[faceIndex(face)];
    checkRingDetectionSize(photo.width, photo.height, std::string("the photo of face ") + faceLetter(face));
  }
  BlockRingDetection detection;
  const double share = 1.0 / static_cast<double>(faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const FaceId face = faces[k];
    const Image& photo = photos[faceIndex(face)];
    const Stopwatch clock;
    const FaceFrame frame = block.face(face);
    DetectedFaceRings rings;
    rings.pxPerMm = {photo.width / frame.widthMm, photo.height / frame.heightMm};
    rings.arl = detector.localize(photo, rings.meanPxPerMm(), progress.part(k * share, (k + 1) * share));
    progress.throwIfCancelled();
    rings.contours = extractContours(rings.arl, face);
    rings.seconds = clock.seconds();
    detection.faces[faceIndex(face)] = std::move(rings);
  }
  return detection;
}

}  // namespace kerf
