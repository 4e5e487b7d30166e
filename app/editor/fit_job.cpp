#include "fit_job.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "field/growth_field.hpp"
#include "fit/distortion_fit.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/pith_fit.hpp"
#include "rings/contours.hpp"
#include "rings/ring_detector.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace fs = std::filesystem;

namespace {

Image fromQImage(const QImage& photo) {
  const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
  Image image(rgb.width(), rgb.height(), 3);
  for (int y = 0; y < rgb.height(); ++y) {
    const uchar* line = rgb.constScanLine(y);
    float* out = image.pixel(0, y);
    for (int i = 0; i < 3 * rgb.width(); ++i) out[i] = line[i] / 255.0f;
  }
  return image;
}

GrayImage8 toGray8(const Image& arl) {
  GrayImage8 gray;
  gray.width = arl.width;
  gray.height = arl.height;
  gray.pixels.resize(static_cast<std::size_t>(arl.width) * arl.height);
  for (int y = 0; y < arl.height; ++y)
    for (int x = 0; x < arl.width; ++x)
      gray.pixels[static_cast<std::size_t>(y) * arl.width + x] =
          static_cast<std::uint8_t>(std::lround(std::clamp(arl.pixel(x, y)[0], 0.0f, 1.0f) * 255.0f));
  return gray;
}

// A part [from, to] of a job's progress.
Progress part(const Progress& progress, double from, double to) {
  Progress sub{nullptr, progress.stop};
  if (progress.report)
    sub.report = [report = progress.report, from, to](double f) { report(from + (to - from) * f); };
  return sub;
}

QString vec3Text(glm::vec3 v, int decimals) {
  return QStringLiteral("(%1, %2, %3)")
      .arg(v.x, 0, 'f', decimals)
      .arg(v.y, 0, 'f', decimals)
      .arg(v.z, 0, 'f', decimals);
}

QString candidateText(const QString& label, const PithCandidate& c, float ringWidthMm) {
  return QStringLiteral(
             "%1: O = %2 mm, V = %3 (tilt %4°, azimuth %5°), %6 mm from the block centre; "
             "iso-contour loss %7 mm = %8 ring spacings")
      .arg(label, vec3Text(c.axis.origin, 3), vec3Text(c.axis.direction, 5))
      .arg(c.tiltDeg, 0, 'f', 2)
      .arg(c.azimuthDeg, 0, 'f', 2)
      .arg(glm::length(c.axis.origin), 0, 'f', 1)
      .arg(c.loss.meanOverFaces, 0, 'f', 4)
      .arg(ringWidthMm > 0 ? c.loss.meanOverFaces / ringWidthMm : 0.0, 0, 'f', 4);
}

}  // namespace

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
                          part(progress, double(done) / withPhoto, double(done + 1) / withPhoto));
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
    const std::string prefix = std::string(1, faceLetter(face)) + "_arl";
    fs::path chosen = folder / (prefix + "-unet.png");
    if (!fs::exists(chosen)) {
      std::vector<fs::path> found;
      for (const auto& entry : fs::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name.rfind(prefix, 0) == 0 && entry.path().extension() == ".png")
          found.push_back(entry.path());
      }
      std::sort(found.begin(), found.end());
      chosen = found.empty() ? fs::path() : found.front();
    }
    if (!chosen.empty()) images[faceIndex(face)] = readRingLocalizationImage(chosen);
  }
  return images;
}

GrowthFitResult fitGrowthField(const std::array<GrayImage8, 6>& images, const Block& block,
                               const WoodParameters& current, const Progress& progress) {
  GrowthFitResult out;
  const Stopwatch extractClock;
  IsoContours contours;
  QStringList perFace;
  for (FaceId face : kAllFaces) {
    const GrayImage8& image = images[faceIndex(face)];
    if (image.empty()) continue;
    const auto pixels = extractIsoContours(image);
    addFaceContours(contours, block, face, {image.width, image.height}, pixels);
    perFace << QStringLiteral("%1 %2").arg(QChar(faceLetter(face))).arg(pixels.size());
  }
  const double extractSeconds = extractClock.seconds();
  if (contours.count() < kMinFitContours || contours.facesWithContours() < 2)
    throw InputError(
        QStringLiteral("too few ring contours to fit the growth field: %1 on %2 faces (at least %3 "
                       "on two faces are needed); detect rings on sharper photos")
            .arg(contours.count())
            .arg(contours.facesWithContours())
            .arg(kMinFitContours)
            .toStdString());
  out.report << QStringLiteral("contours per face: %1").arg(perFace.join(", "));
  progress.throwIfCancelled();

  const PithFitResult pith = fitPith(contours, block, PithFitOptions{}, part(progress, 0.0, 0.45));
  for (const std::string& w : pith.warnings)
    out.report << QStringLiteral("warning: %1").arg(QString::fromStdString(w));

  const Stopwatch ringClock;
  const RingLevelEstimate rings = estimateRingLevels(pith.best.axis, block, images);
  const double ringSeconds = ringClock.seconds();
  out.report << QStringLiteral("%1 contours, %2 points (%3 used by the continuous fit), %4 grid candidates")
                    .arg(pith.contours)
                    .arg(pith.points)
                    .arg(pith.fitPoints)
                    .arg(pith.gridCandidates);
  out.report << candidateText(QStringLiteral("pith"), pith.best, rings.ringWidthMm);
  out.report << QStringLiteral("rings: width %1 mm, phase %2 (%3 rings found)")
                    .arg(rings.ringWidthMm, 0, 'f', 4)
                    .arg(rings.ringOffset, 0, 'f', 4)
                    .arg(rings.peaksMm.size());
  out.ambiguous = pith.ambiguous;
  if (pith.flipped) {
    out.report << QStringLiteral("ambiguity (Mokume B.1): %1")
                      .arg(pith.ambiguous
                               ? QStringLiteral(
                                     "AMBIGUOUS: the mirrored pith explains the rings almost as well")
                               : QStringLiteral("the mirrored pith is clearly worse"));
    out.report << candidateText(QStringLiteral("other candidate"), *pith.flipped, rings.ringWidthMm);
  } else {
    out.report << QStringLiteral(
        "ambiguity (Mokume B.1): none (the mirrored start converged to the same axis)");
  }

  WoodParameters params = current;
  params.pithOrigin = pith.best.axis.origin;
  params.pithTilt = pith.best.tiltDeg;
  params.pithAzimuth = pith.best.azimuthDeg;
  // The axis exactly as the model rebuilds it from the parameters.
  const PithAxis axis = PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth);
  const float width0 = rings.ringWidthMm;
  const DistortionFitResult d = fitDistortions(contours, block, axis, width0, {}, part(progress, 0.45, 0.95));
  const GrowthField field(axis, width0, d.rates);
  const Stopwatch remapClock;
  const RingLevelEstimate fitted = estimateRingLevels(
      [&field, width0](glm::vec3 p) { return static_cast<double>(field.evaluate(p)) * width0; }, block,
      images);
  std::vector<double> levels;
  for (float peak : fitted.peaksMm) levels.push_back(peak / width0);
  GrowthRates rates = remapRingsToWholeYears(d.rates, width0, levels);
  // Rates scaled to a median of 1 and the ring width with them (the field is unchanged), so
  // growth.ring_width stays the typical ring width in mm.
  std::vector<float> sorted = rates.rates;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float median = sorted[sorted.size() / 2];
  for (float& r : rates.rates) r /= median;
  params.ringWidth = width0 / median;
  params.ringOffset = 0.0f;
  const GrowthField saved(axis, params.ringWidth, rates);
  const IsoContourLoss finalLoss = isoContourLoss(contours, saved, 1.0);
  const double remapSeconds = remapClock.seconds();
  const double toRings = fitted.ringWidthMm > 0 ? width0 / fitted.ringWidthMm : 1.0;
  out.report << QStringLiteral(
                    "distortions: %1 x %2 x %3 rates, iso-contour loss %4 -> %5 ring spacings, %6 iterations")
                    .arg(d.rates.heights)
                    .arg(d.rates.azimuths)
                    .arg(d.rates.radii)
                    .arg(d.lossBefore.meanOverFaces, 0, 'f', 4)
                    .arg(d.lossAfter.meanOverFaces * toRings, 0, 'f', 4)
                    .arg(d.iterations);
  out.report << QStringLiteral("fitted field: iso-contour loss %1 ring spacings, typical ring width %2 mm")
                    .arg(finalLoss.meanOverFaces, 0, 'f', 4)
                    .arg(params.ringWidth, 0, 'f', 4);
  out.report << QStringLiteral(
                    "time: contours %1 s, grid search %2 s, refinement %3 s, rings %4 s, distortions %5 s, "
                    "ring placement %6 s")
                    .arg(extractSeconds, 0, 'f', 3)
                    .arg(pith.gridSeconds, 0, 'f', 3)
                    .arg(pith.refineSeconds, 0, 'f', 3)
                    .arg(ringSeconds, 0, 'f', 3)
                    .arg(d.seconds, 0, 'f', 3)
                    .arg(remapSeconds, 0, 'f', 3);
  progress.set(1.0);
  validate(params);
  out.params = params;
  out.rates = std::move(rates);
  out.lossRings = finalLoss.meanOverFaces;
  return out;
}

}  // namespace kerf
