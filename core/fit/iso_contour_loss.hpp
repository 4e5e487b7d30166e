#pragma once
// Ring contours lifted onto the block, and the iso-contour loss of Mokume Eq. 2 evaluated on them.
//
// Loss (as the authors' code computes it, MOKUME_CONVENTIONS.md C): for face f,
//   L_f = sum_c sum_{p in c} |g(p) - med_c| / sum_c |c|,
// the mean absolute deviation of the face's contour points from their own contour's (lower) median
// field value; Eq. 2 writes the mean, the code uses the median, which is robust to stray pixels.
// Kerf reports
//   - meanOverFaces: the mean of L_f over the faces that have contours, in field units;
//   - normalized: meanOverFaces divided by the field's median ring spacing (in the same units), i.e. the
//     typical error in rings. For the authors' CN03 result this is 0.018023 * 40 mm / 6 / 3.764 mm
//     = 0.032 ring spacings;
//   - sumOverFaces: sum_f L_f. The authors log 10 * sum_f L_f with g in cube units (40 mm), so for g in
//     mm their number is 10 * sumOverFaces / 40 (see mokumeLoggedLoss()).
#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "geometry/block.hpp"

namespace kerf {

class GrowthField;
struct RingTrace;

struct IsoContours {
  std::vector<glm::vec3> points;  // block mm, contour after contour
  std::vector<int> begin{0};      // contour c holds points [begin[c], begin[c + 1])
  std::vector<FaceId> face;       // the face of each contour
  // The year of each contour when the user numbered it (numbered traces, learned-inference paper
  // Sec. 3.2.3); none for contours of a ring-localization image.
  std::vector<std::optional<int>> year;

  int count() const { return static_cast<int>(face.size()); }
  int size(int c) const { return begin[c + 1] - begin[c]; }
  int contoursOnFace(FaceId f) const;
  int facesWithContours() const;
  int numberedContours() const;
};

// A bootstrap replicate (fit/ring_uncertainty.hpp): as many contours as `contours` holds, drawn whole with
// replacement (a uniform draw per contour from a seeded generator: the same seed, the same replicate).
IsoContours resampledContours(const IsoContours& contours, std::uint64_t seed);

// Lifts pixel contours of one face image (imageSize pixels covering the face) onto the block. Pixel
// (x, y) goes to continuous image coordinates (x + pixelOffset, y + pixelOffset): 0.5 is Kerf's pixel
// centre; 0 reproduces the Mokume authors' placement (their numbers, e.g. their CN03 loss).
void addFaceContours(IsoContours& contours, const Block& block, FaceId face, glm::ivec2 imageSize,
                     const std::vector<std::vector<glm::ivec2>>& pixelContours, float pixelOffset = 0.5f);

// Adds ring traces (face mm polylines, rings/annotations.hpp) resampled every spacingMm, with their
// year numbers. Traces with fewer than two points are skipped.
void addTraceContours(IsoContours& contours, const Block& block, const std::vector<RingTrace>& traces,
                      float spacingMm = 0.15f);

struct IsoContourLoss {
  std::array<double, 6> perFace{};  // L_f, field units (0 where a face has no contours)
  std::array<int, 6> contours{};    // per face
  std::array<int, 6> points{};      // per face
  double meanOverFaces = 0;         // mean of L_f over faces with contours
  double sumOverFaces = 0;          // sum of L_f
  double normalized = 0;            // meanOverFaces / ringSpacing (0 without a spacing)
};

// The loss from the field values at every contour point (values.size() == contours.points.size()).
// ringSpacing: the field's median ring spacing in field units (1 for a field in years with rings at
// whole years; the ring width for a distance field in mm); <= 0 leaves `normalized` at 0.
IsoContourLoss isoContourLoss(const IsoContours& contours, const std::vector<double>& values,
                              double ringSpacing);
// The same, evaluating g at the points (in parallel; g must be thread-safe).
IsoContourLoss isoContourLoss(const IsoContours& contours, const std::function<double(glm::vec3)>& g,
                              double ringSpacing);
// For a Kerf growth field (years): values in years, spacing given in years (1 with unit rate steps).
IsoContourLoss isoContourLoss(const IsoContours& contours, const GrowthField& field, double ringSpacingYears);

// The authors' logged number, 10 * sum over faces with g in cube units, from a loss whose field
// is in mm: 10 * sumOverFaces / cubeSideMm.
inline double mokumeLoggedLoss(const IsoContourLoss& lossMm, double cubeSideMm = 40.0) {
  return 10.0 * lossMm.sumOverFaces / cubeSideMm;
}

// Lower median of v (v is reordered), as torch.median.
double lowerMedian(std::vector<double>& v);

}  // namespace kerf
