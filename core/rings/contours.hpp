#pragma once
// Ring contours from a ring-localization image (Mokume Sec. 5.1.2), extracted exactly as the Mokume
// authors' code does it (shared/reference/MOKUME_CONVENTIONS.md section C), so that Kerf's contours of
// a Mokume sample are the very pixel lists their growth-field fitting used:
//
//   1. mask = ARL grey > 200/255 (8-bit value, as cv2.threshold(..., 200, 255, THRESH_BINARY));
//   2. cv::findContours(mask, RETR_TREE, CHAIN_APPROX_NONE): the closed pixel boundaries (outer and
//      inner) of every bright band;
//   3. each closed contour is cut at the points near the image border ("edge points"): walking it,
//      the points before the first edge point are held back; at every edge point the running segment
//      is kept if it has more than `minPoints` points, and a new segment starts with that edge point;
//      at the end the held-back head is appended to the last segment (wrap-around), kept if it has more
//      than `minPoints` points. A contour that never comes near the border is kept whole (if it has
//      more than `minPoints` points: the size rule applies to every piece; this reproduces the
//      authors' counts, 10/19/20/20/24/8 contours on CN03's faces A..F).
//
// So a band crossing the face normally gives two open contours, one along each of its edges.
//
// Pixel convention: FaceContour::pixels holds integer pixel indices (x = column, y = row) of the ARL
// image, in the order findContours walks them. In Kerf's continuous image coordinates the pixel's
// centre is (x + 0.5, y + 0.5) (docs/coordinates.md); the Mokume authors lift the same pixel to the
// point at (x, y) instead (see PixelAnchor).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "geometry/block.hpp"
#include "image/image.hpp"

namespace kerf {

struct FaceContour {
  FaceId face = FaceId::A;
  std::vector<glm::ivec2> pixels;  // (column, row) pixel indices along the contour
};

struct ContourOptions {
  // ARL values (0..1) are quantised to 8 bits (round(v * 255)) and pixels with a value > threshold
  // are "ring". 200 is the authors' value.
  int threshold8 = 200;
  // A point is an edge point if x <= margin, x >= width - margin, y <= margin or y >= height - margin
  // (the authors: x <= 5 or x >= 251 on a 256 px face). -1: 5 px at 256 px, scaled with the image
  // side (round(5 * side / 256), at least 1), separately for x and y.
  int margin = -1;
  // Segments are kept only with more than this many points. -1: 32 at 256 px, scaled with the larger
  // image side (round(32 * side / 256), at least 2).
  int minPoints = -1;
};

// Contours of one face's ring-localization image (values 0..1; the first channel is used). An empty
// image gives no contours.
std::vector<FaceContour> extractContours(const Image& arl, FaceId face, const ContourOptions& options = {});

// Where a contour pixel is lifted to: Kerf's pixel centre (x + 0.5, y + 0.5), or the Mokume authors'
// point (x, y) (use it to reproduce their numbers exactly).
enum class PixelAnchor { KerfCentre, MokumeCorner };

// The contour's pixels as points on the block face (block mm), for an ARL image of imageSize pixels
// covering the whole face.
std::vector<glm::vec3> contourToBlock(const FaceContour& contour, const Block& block, glm::ivec2 imageSize,
                                      PixelAnchor anchor = PixelAnchor::KerfCentre);

}  // namespace kerf
