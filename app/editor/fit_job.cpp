#include "fit_job.hpp"

#include <algorithm>
#include <cmath>

#include "fit/growth_field_fit.hpp"
#include "fit/ring_uncertainty_fit.hpp"
#include "qt_image.hpp"
#include "rings/detect_block_rings.hpp"
#include "rings/learned_ring_detector.hpp"
#include "util/error.hpp"

namespace kerf {

namespace fs = std::filesystem;

int RingDetection::contourCount() const {
  int n = 0;
  for (const auto& face : contours) n += static_cast<int>(face.size());
  return n;
}

RingDetection detectRings(const std::array<QImage, 6>& photos, const Block& block,
                          const std::string& detector, const Progress& progress) {
  if (std::all_of(photos.begin(), photos.end(), [](const QImage& photo) { return photo.isNull(); }))
    throw InputError(
        "there are no face photos to detect rings on; open a sample folder or drop photos on the faces");
  std::array<Image, 6> images;
  for (int i = 0; i < 6; ++i)
    if (!photos[i].isNull()) images[i] = fromQImage(photos[i]);
  const BlockRingDetection found = detectBlockRings(images, block, {}, progress, ringDetectorNamed(detector));
  RingDetection detection;
  detection.detector = detector;
  for (int i = 0; i < 6; ++i) {
    if (!found.faces[i]) continue;
    for (const FaceContour& contour : found.faces[i]->contours)
      detection.contours[i].push_back(contour.pixels);
    detection.arl[i] = toGray8(found.faces[i]->arl);
    detection.seconds[i] = found.faces[i]->seconds;
    ++detection.facesDetected;
  }
  return detection;
}

std::vector<RingTrace> detectedRingTraces(const RingDetection& detection, const Block& block) {
  std::vector<RingTrace> traces;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (detection.arl[i].width <= 0) continue;
    std::vector<FaceContour> contours;
    for (const auto& pixels : detection.contours[i]) contours.push_back({face, pixels});
    auto faceTraces =
        tracesFromContours(contours, block, glm::ivec2(detection.arl[i].width, detection.arl[i].height));
    traces.insert(traces.end(), faceTraces.begin(), faceTraces.end());
  }
  return traces;
}

std::array<std::vector<QPolygonF>, 6> contourPolylines(const RingDetection& detection) {
  std::array<std::vector<QPolygonF>, 6> lines;
  for (int i = 0; i < 6; ++i)
    for (const auto& contour : detection.contours[i]) {
      QPolygonF polyline;
      polyline.reserve(static_cast<int>(contour.size()));
      for (glm::ivec2 p : contour) polyline << QPointF(p.x + 0.5, p.y + 0.5);
      lines[i].push_back(polyline);
    }
  return lines;
}

std::array<QSize, 6> detectionSizes(const RingDetection& detection) {
  std::array<QSize, 6> sizes;
  for (int i = 0; i < 6; ++i) sizes[i] = QSize(detection.arl[i].width, detection.arl[i].height);
  return sizes;
}

std::array<GrayImage8, 6> readFolderRingImages(const fs::path& folder) {
  std::array<GrayImage8, 6> images;
  if (folder.empty() || !fs::is_directory(folder)) return images;
  for (FaceId face : kAllFaces) {
    const fs::path chosen = findRingLocalizationImage(folder, face);
    if (!chosen.empty()) images[faceIndex(face)] = readRingLocalizationImage(chosen);
  }
  return images;
}

GrowthFitResult fitGrowthField(const std::array<GrayImage8, 6>& images, const Block& block,
                               const WoodParameters& current, const std::array<QImage, 6>& photos,
                               const Progress& progress, const std::vector<RingTrace>& traces,
                               const GrowthFitPreview& preview, const std::vector<KnotMark>& knotMarks,
                               const FaceSet& heldOut) {
  GrowthFieldFitInput input;
  input.heldOut = heldOut;  // dropped by the fit itself, whatever of these faces is below
  input.rings = images;
  input.traces = traces;
  input.knotMarks = knotMarks;  // marks sharing an id: one knot of the field (Mokume Sec. 5.2.4)
  // Detected contours became the document's traces (corrected by the user): the images then only place
  // the rings and give the image term.
  input.contoursFromImages = traces.empty();
  for (int i = 0; i < 6; ++i)
    if (!photos[i].isNull()) input.photos[i] = fromQImage(photos[i]);
  GrowthFieldFitOptions options;
  options.minContours = kMinFitContours;
  options.minFaces = kMinFitFaces;
  if (preview)
    options.preview = [&](const WoodParameters& params, const std::optional<GrowthRates>& rates) {
      preview(params,
              rates ? *rates
                    : GrowthRates::uniform(block, PithAxis::fromAngles(params.pithOrigin, params.pithTilt,
                                                                       params.pithAzimuth)));
    };
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(input, block, current, options, progress);
  GrowthFitResult out;
  out.params = fit.params;
  out.rates = *fit.rates;
  out.knots = fit.knots;
  out.report = formatGrowthFieldFitReport(fit.report);
  out.knotOutlines = fit.report.knotOutlines;
  out.ambiguous = fit.report.pith.ambiguous;
  out.lossRings = fit.report.finalLossRings;
  for (const ContourResidual& c : fit.contours) {
    FittedContour f{c.face, {}, c.residualRings};
    for (const glm::vec3& p : c.points) f.pointsMm.push_back(blockToFaceMm(block, c.face, p));
    out.contours.push_back(std::move(f));
  }
  options.preview = nullptr;  // it refers to this call's arguments
  out.options = options;
  out.input = std::make_shared<const GrowthFieldFitInput>(std::move(input));
  if (fit.alternative && fit.alternative->rates)
    out.alternative = GrowthFitResult::Alternative{fit.alternative->params, *fit.alternative->rates,
                                                   fit.alternative->finalLossRings, fit.alternative->knots};
  return out;
}

RingUncertainty estimateFitUncertainty(const GrowthFitResult& fit, const Block& block,
                                       const Progress& progress) {
  if (!fit.input) throw InputError("the fit kept no input to estimate how sure it is");
  GrowthFieldFitResult fitted;
  fitted.params = fit.params;
  fitted.rates = fit.rates;
  fitted.knots = fit.knots;
  return estimateRingUncertainty(*fit.input, block, fitted, fit.options, {}, progress);
}

}  // namespace kerf
