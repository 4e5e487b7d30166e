#include "fit_job.hpp"

#include <algorithm>
#include <cmath>

#include "fit/growth_field_fit.hpp"
#include "qt_image.hpp"
#include "rings/contours.hpp"
#include "rings/ring_detector.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace fs = std::filesystem;

int RingDetection::contourCount() const {
  int n = 0;
  for (const auto& face : contours) n += static_cast<int>(face.size());
  return n;
}

RingDetection detectRings(const std::array<QImage, 6>& photos, const Block& block, const Progress& progress) {
  int withPhoto = 0;
  for (const QImage& photo : photos) withPhoto += !photo.isNull();
  if (withPhoto == 0)
    throw InputError(
        "there are no face photos to detect rings on; open a sample folder or drop photos on the faces");
  const ClassicalRingDetector detector;
  RingDetection detection;
  int done = 0;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (photos[i].isNull()) continue;
    const Stopwatch clock;
    const FaceFrame frame = block.face(face);
    const float pxPerMm = 0.5f * (photos[i].width() / frame.widthMm + photos[i].height() / frame.heightMm);
    const Image arl =
        detector.localize(fromQImage(photos[i]), pxPerMm,
                          progress.part(double(done) / withPhoto, double(done + 1) / withPhoto));
    progress.throwIfCancelled();
    for (const FaceContour& contour : extractContours(arl, face))
      detection.contours[i].push_back(contour.pixels);
    detection.arl[i] = toGray8(arl);
    detection.seconds[i] = clock.seconds();
    ++detection.facesDetected;
    ++done;
  }
  return detection;
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
  options.minFaces = 2;
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
  for (const std::string& line : formatGrowthFieldFitReport(fit.report))
    out.report << QString::fromStdString(line);
  out.ambiguous = fit.report.pith.ambiguous;
  out.lossRings = fit.report.finalLossRings;
  for (const ContourResidual& c : fit.contours) {
    FittedContour f{c.face, {}, c.residualRings};
    for (const glm::vec3& p : c.points) f.pointsMm.push_back(blockToFaceMm(block, c.face, p));
    out.contours.push_back(std::move(f));
  }
  if (fit.alternative && fit.alternative->rates)
    out.alternative = GrowthFitResult::Alternative{fit.alternative->params, *fit.alternative->rates,
                                                   fit.alternative->finalLossRings, fit.alternative->knots};
  return out;
}

}  // namespace kerf
