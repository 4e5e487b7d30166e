#include "fit/iso_contour_loss.hpp"

#include "rings/annotations.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "field/growth_field.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

int IsoContours::contoursOnFace(FaceId f) const {
  return static_cast<int>(std::count(face.begin(), face.end(), f));
}

int IsoContours::facesWithContours() const {
  int n = 0;
  for (FaceId f : kAllFaces) n += contoursOnFace(f) > 0;
  return n;
}

void addFaceContours(IsoContours& contours, const Block& block, FaceId face, glm::ivec2 imageSize,
                     const std::vector<std::vector<glm::ivec2>>& pixelContours, float pixelOffset) {
  for (const auto& contour : pixelContours) {
    if (contour.empty()) continue;
    for (const glm::ivec2& p : contour) {
      contours.points.push_back(
          block.imageToBlock(face, glm::vec2(p.x + pixelOffset, p.y + pixelOffset), imageSize));
    }
    contours.begin.push_back(static_cast<int>(contours.points.size()));
    contours.face.push_back(face);
    contours.year.push_back(std::nullopt);
  }
}

void addTraceContours(IsoContours& contours, const Block& block, const std::vector<RingTrace>& traces,
                      float spacingMm) {
  for (const RingTrace& trace : traces) {
    if (trace.points.size() < 2) continue;
    RingTrace dense = trace;
    dense.points = resamplePolyline(trace.points, spacingMm);
    for (const glm::vec3& p : traceToBlock(dense, block)) contours.points.push_back(p);
    contours.begin.push_back(static_cast<int>(contours.points.size()));
    contours.face.push_back(trace.face);
    contours.year.push_back(trace.year);
  }
}

int IsoContours::numberedContours() const {
  return static_cast<int>(
      std::count_if(year.begin(), year.end(), [](const auto& y) { return y.has_value(); }));
}

IsoContours resampledContours(const IsoContours& contours, std::uint64_t seed) {
  IsoContours out;
  if (contours.count() == 0) return out;
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> pick(0, contours.count() - 1);
  for (int n = 0; n < contours.count(); ++n) {
    const int c = pick(random);
    out.points.insert(out.points.end(), contours.points.begin() + contours.begin[c],
                      contours.points.begin() + contours.begin[c + 1]);
    out.begin.push_back(static_cast<int>(out.points.size()));
    out.face.push_back(contours.face[c]);
    out.year.push_back(contours.year[c]);
  }
  return out;
}

double lowerMedian(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const std::size_t k = (v.size() - 1) / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

IsoContourLoss isoContourLoss(const IsoContours& contours, const std::vector<double>& values,
                              double ringSpacing) {
  if (values.size() != contours.points.size()) {
    throw InputError("iso-contour loss: one field value per contour point is needed");
  }
  IsoContourLoss loss;
  std::array<double, 6> sum{};
  std::vector<double> scratch;
  for (int c = 0; c < contours.count(); ++c) {
    const int f = faceIndex(contours.face[c]);
    scratch.assign(values.begin() + contours.begin[c], values.begin() + contours.begin[c + 1]);
    if (scratch.empty()) continue;
    const double med = lowerMedian(scratch);
    double s = 0;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i) s += std::abs(values[i] - med);
    sum[f] += s;
    loss.contours[f] += 1;
    loss.points[f] += contours.size(c);
  }
  int faces = 0;
  for (int f = 0; f < 6; ++f) {
    if (loss.points[f] == 0) continue;
    loss.perFace[f] = sum[f] / loss.points[f];
    loss.sumOverFaces += loss.perFace[f];
    ++faces;
  }
  loss.meanOverFaces = faces ? loss.sumOverFaces / faces : 0.0;
  loss.normalized = ringSpacing > 0 ? loss.meanOverFaces / ringSpacing : 0.0;
  return loss;
}

IsoContourLoss isoContourLoss(const IsoContours& contours, const std::function<double(glm::vec3)>& g,
                              double ringSpacing) {
  std::vector<double> values(contours.points.size());
  const int chunk = 1024;
  const int chunks = static_cast<int>((values.size() + chunk - 1) / chunk);
  parallelRows(chunks, [&](int k) {
    const std::size_t end = std::min(values.size(), static_cast<std::size_t>(k + 1) * chunk);
    for (std::size_t i = static_cast<std::size_t>(k) * chunk; i < end; ++i) values[i] = g(contours.points[i]);
  });
  return isoContourLoss(contours, values, ringSpacing);
}

IsoContourLoss isoContourLoss(const IsoContours& contours, const GrowthField& field,
                              double ringSpacingYears) {
  return isoContourLoss(
      contours, [&field](glm::vec3 p) { return static_cast<double>(field.evaluate(p)); }, ringSpacingYears);
}

}  // namespace kerf
