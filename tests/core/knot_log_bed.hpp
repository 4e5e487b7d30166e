#pragma once
// One block of the knot test bed end to end (issue 19 item 3; docs/knots.md, "A knot test bed cut from
// the spruce log"): cut from the log (log_cut_blocks.hpp), its faces rendered as photos
// (log_block_photos.hpp), the knot marks set where the true knot axes meet the faces, then Kerf's own
// pipeline as `kerf-cli fit` runs it: ring detection on the photos (rings/detect_block_rings.hpp) and the
// whole growth-field fit with the knots from the marks (fit/growth_field_fit.hpp, Mokume Sec. 5.2 and
// 5.2.4). The fit sees the photos, the block's size and the marks only; where the block lies in the log
// is known to the comparison alone (knot_fit_truth.hpp). Shared by bench/knot_log_testbed.cpp and
// tests/core/test_knot_log_bed.cpp.
#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "field/knot_field.hpp"
#include "fit/block_knot_fit.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/iso_contours.hpp"
#include "image/gray_image.hpp"
#include "io/image.hpp"
#include "knot_fit_truth.hpp"
#include "log_block_photos.hpp"
#include "log_cut_blocks.hpp"
#include "params/parameter_schema.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "rings/detect_block_rings.hpp"
#include "util/resource_usage.hpp"

namespace kerf::testing {

struct BedRunOptions {
  BlockPhotoOptions photos;
  float cutStepMm = 0.1f;         // grid of the hidden cut
  bool withoutMarks = true;       // also fit with no marks, the reference the knot fit should beat on the cut
  std::filesystem::path saveDir;  // where to write the photos and ring images to look at (empty: nowhere)
  // The fit's options, as `kerf-cli fit` sets them; the test turns off the mirrored candidate to save time.
  GrowthFieldFitOptions fit = [] {
    GrowthFieldFitOptions o;
    o.minContours = kMinFitContours;
    o.minFaces = kMinFitFaces;
    return o;
  }();
};

// One knot of a block, fitted against the truth.
struct BedKnotResult {
  int knot = 0;                      // log index (also its marks' id)
  bool deadInBlock = false;          // the measured knot dies before it leaves the block
  bool fitted = false;               // the fit returned a knot for its marks
  std::array<FaceId, 2> faces{};     // the marked faces (entry, exit)
  double faceAngleDeg = 0;           // true axis against the entry face's normal
  double axisDeg = 0;                // fitted axis against the true one (the chord between the marks)
  std::array<double, 2> offsetMm{};  // fitted axis against the mark, on each marked face's plane
  std::array<double, 2> trueDiameterMm{}, fittedDiameterMm{};
  CutRingErrors cut, cutWithoutMarks;  // rings on the hidden cut along this knot
  // A diagnosis, not a fit: the same fitted field with this knot's speed scaled so that its diameter
  // matches the truth's (the mean of both faces' ratios). Better rings than `cut`: the fit stopped short
  // of the knot's size; worse: the block model explains the rings better with a thinner knot.
  CutRingErrors cutAtTrueSize;
  // The same question on the data the fit saw: the iso-contour error (mean |G - contour median|, ring
  // spacings; fit/block_knot_fit.hpp nearKnotLoss) of the detected contours' points within a knot
  // diameter of the true axis, with the fitted knot and with it at the true size.
  double contourLoss = 0, contourLossAtTrueSize = 0;
  // The detected contours against the truth (knot_fit_truth.hpp contourErrors), mm: all, near this knot.
  CutRingErrors detectedContours;
};

struct BedBlockResult {
  BedBlockSpec spec;
  bool withDeath = true;  // the log as measured; false: the block's knots alive to the bark
  Board board;
  int contours = 0;
  std::vector<BedKnotResult> knots;
  // The fitted pith against the log's (block frame): the angle, and the distance at the block's centre;
  // with the marks and without them.
  double pithDeg = 0, pithMm = 0, pithDegWithoutMarks = 0, pithMmWithoutMarks = 0;
  GrowthFieldFitReport report;  // the fit with the marks (stage timings, knot entries)
  double fitSeconds = 0;
  std::string note;  // why something is missing
};

// The fitted field of a whole fit: its stem and its knots (Mokume Eq. 7, Eq. 6).
struct FittedBlockField {
  GrowthField stem;
  BlockKnots knots;
  FittedBlockField(const WoodParameters& params, const GrowthRates& rates, std::vector<BlockKnot> blockKnots)
      : stem(params, rates),
        knots(std::move(blockKnots), KnotSettings::fromParameters(params), params.ringWidth) {}
  explicit FittedBlockField(const GrowthFieldFitResult& fit)
      : FittedBlockField(fit.params, *fit.rates, fit.knots) {}
  float operator()(const glm::vec3& p) const {
    const Cylindrical c = stem.axis().toCylindrical(p);
    return knots.merge(p, stem.evaluate(c), c.radius).time;
  }
};

// The fitted pith axis against the log's pith through the block: angle (deg) and distance (mm) from the
// point of the true pith nearest the block's centre.
inline void pithError(const LogModel& log, const Board& board, const WoodParameters& fitted, double& deg,
                      double& mm) {
  const glm::vec2 a = log.stem.pithAt(board.center.z - 30.0f), b = log.stem.pithAt(board.center.z + 30.0f);
  const glm::vec3 p0 = logToBlock(board, glm::vec3(a, board.center.z - 30.0f));
  const glm::vec3 p1 = logToBlock(board, glm::vec3(b, board.center.z + 30.0f));
  const glm::vec3 v = glm::normalize(p1 - p0);
  const glm::vec3 nearest = p0 + glm::dot(-p0, v) * v;
  const PithAxis axis = PithAxis::fromAngles(fitted.pithOrigin, fitted.pithTilt, fitted.pithAzimuth);
  deg = std::min(angleBetweenDeg(axis.direction, v), angleBetweenDeg(-axis.direction, v));
  mm = axis.toCylindrical(nearest, false).radius;
}

inline GrowthFieldFitResult fitBedPhotos(const std::array<Image, 6>& photos, const BlockRingDetection& rings,
                                         const Block& block, const std::vector<KnotMark>& marks,
                                         const GrowthFieldFitOptions& options) {
  GrowthFieldFitInput input;
  for (int i = 0; i < 6; ++i) {
    input.photos[i] = photos[i];
    if (rings.faces[i]) input.rings[i] = toGray8(rings.faces[i]->arl);
  }
  input.knotMarks = marks;
  return fitGrowthFieldToSample(input, block, WoodParameters{}, options);
}

inline BedBlockResult runBedBlock(const LogModel& measured, const BedBlockSpec& spec, bool withDeath,
                                  const BedRunOptions& options = {}) {
  BedBlockResult out;
  out.spec = spec;
  out.withDeath = withDeath;
  out.board = placeBedBlock(measured, spec);
  const LogModel log = withDeath ? measured : withoutDeaths(measured, spec.knots);
  const WoodParameters defaults;
  const KnotField field(log, KnotSettings::fromParameters(defaults));
  const WoodColorMap colours =
      log.colorMap.empty() ? woodColorMapFromParameters(defaults, log.stem.maxRadius()) : log.colorMap;
  const Block block = out.board.block();
  const std::array<Image, 6> photos = renderLogBlockFaces(field, colours, out.board, options.photos);
  const BlockRingDetection rings = detectBlockRings(photos, block);
  out.contours = rings.contourCount();
  if (!options.saveDir.empty()) {
    std::filesystem::create_directories(options.saveDir);
    const std::string stem = spec.name + (withDeath ? "" : "_no_death") + "_";
    for (FaceId f : kAllFaces) {
      const std::string face(1, faceLetter(f));
      writeImage(options.saveDir / (stem + face + "_col.png"), photos[faceIndex(f)]);
      if (rings.faces[faceIndex(f)])
        writeImage(options.saveDir / (stem + face + "_arl.png"), rings.faces[faceIndex(f)]->arl);
    }
  }

  std::vector<KnotMark> marks;
  std::vector<std::vector<AxisCrossing>> crossings;
  for (int k : spec.knots) {
    crossings.push_back(axisCrossings(log, k, out.board));
    for (const KnotMark& m : knotMarksAtCrossings(log, k, out.board)) marks.push_back(m);
  }
  IsoContours contours;  // as the fit extracts them from the ring images
  for (FaceId f : kAllFaces)
    if (const auto& face = rings.faces[faceIndex(f)]) {
      const GrayImage8 image = toGray8(face->arl);
      addFaceContours(contours, block, f, {image.width, image.height}, extractIsoContours(image));
    }
  const Stopwatch clock;
  const GrowthFieldFitResult fit = fitBedPhotos(photos, rings, block, marks, options.fit);
  out.fitSeconds = clock.seconds();
  if (!options.saveDir.empty()) {  // the fitted block's faces beside the photos, to look at
    const WoodModel model(block, fit.params, *fit.rates, fit.knots);
    const std::string stem = spec.name + (withDeath ? "" : "_no_death") + "_";
    for (FaceId f : kAllFaces) {
      const Image& photo = photos[faceIndex(f)];
      writeImage(options.saveDir / (stem + std::string(1, faceLetter(f)) + "_fitted.png"),
                 renderFace(model, f, {photo.width, photo.height}, 2));
    }
  }
  out.report = fit.report;
  pithError(log, out.board, fit.params, out.pithDeg, out.pithMm);
  std::optional<GrowthFieldFitResult> plain;
  if (options.withoutMarks) {
    plain = fitBedPhotos(photos, rings, block, {}, options.fit);
    pithError(log, out.board, plain->params, out.pithDegWithoutMarks, out.pithMmWithoutMarks);
  }

  // The truth in the block frame, with only the knots that can reach the block (the rest change nothing).
  std::vector<int> reaching;
  {
    glm::vec3 lo(1e30f), hi(-1e30f);
    const glm::vec3 h = block.halfSize();
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p =
          out.board.toLog(glm::vec3((c & 1) ? h.x : -h.x, (c & 2) ? h.y : -h.y, (c & 4) ? h.z : -h.z));
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    field.cull(lo, hi, field.allKnots(), reaching);
  }
  const ScalarField truth = [&](const glm::vec3& q) {
    return field.evaluate(out.board.toLog(q), reaching).time;
  };
  const FittedBlockField fitted(fit);
  std::optional<FittedBlockField> fittedPlain;
  if (plain) fittedPlain.emplace(*plain);

  for (std::size_t i = 0; i < spec.knots.size(); ++i) {
    const int k = spec.knots[i];
    const std::vector<AxisCrossing>& c = crossings[i];
    BedKnotResult r;
    r.knot = k;
    if (c.size() != 2) {
      out.note += "knot " + std::to_string(k) + " does not cross the block twice; ";
      out.knots.push_back(r);
      continue;
    }
    r.faces = {c[0].face, c[1].face};
    r.deadInBlock = measured.knots[k].deathDistance < c[1].distance;
    const glm::vec3 chord = c[1].point - c[0].point;
    r.faceAngleDeg = angleBetweenDeg(chord, -block.face(c[0].face).normal);
    const std::vector<glm::vec3> axis = trueAxisInBlock(log, k, out.board, c[0].distance, c[1].distance);
    for (int e = 0; e < 2; ++e) r.trueDiameterMm[e] = trueKnotDiameter(field, out.board, k, c[e]);
    const float nearMm = static_cast<float>(r.trueDiameterMm[0] + r.trueDiameterMm[1]) * 0.5f;
    const auto near = [&](const glm::vec3& p) { return distanceToPolyline(p, axis) < nearMm; };
    const HiddenCut cut = cutAlongKnot(c[0], c[1]);
    if (fittedPlain)
      r.cutWithoutMarks = cutRingErrors(truth, *fittedPlain, block, cut, near, options.cutStepMm);
    const auto found =
        std::find_if(fit.knots.begin(), fit.knots.end(), [&](const BlockKnot& b) { return b.id == k; });
    if (found == fit.knots.end()) {
      out.note += "no fitted knot for knot " + std::to_string(k) + "; ";
      out.knots.push_back(r);
      continue;
    }
    r.fitted = true;
    r.axisDeg = angleBetweenDeg(found->direction, chord);
    for (int e = 0; e < 2; ++e) {
      const glm::vec3 onFace = axisOnFacePlane(*found, block, c[e].face);
      r.offsetMm[e] = glm::length(onFace - c[e].point);
      r.fittedDiameterMm[e] = fittedKnotDiameter(fitted.stem, *found, onFace, fitted.knots.settings());
    }
    r.cut = cutRingErrors(truth, fitted, block, cut, near, options.cutStepMm);
    std::vector<BlockKnot> resized = fit.knots;
    for (BlockKnot& b : resized)
      if (b.id == k) {
        const double ratio = 0.5 * (r.trueDiameterMm[0] / std::max(r.fittedDiameterMm[0], 1e-3) +
                                    r.trueDiameterMm[1] / std::max(r.fittedDiameterMm[1], 1e-3));
        const KnotSettings s = KnotSettings::fromParameters(fit.params);
        b.speed =
            std::min(static_cast<float>(b.speed * ratio), 0.9f * std::min(s.knotReachStart, s.knotReachEnd));
      }
    const FittedBlockField trueSize(fit.params, *fit.rates, resized);
    r.cutAtTrueSize = cutRingErrors(truth, trueSize, block, cut, near, options.cutStepMm);
    std::vector<bool> nearPoints;
    std::vector<double> withFitted, withTrueSize;
    for (const glm::vec3& p : contours.points) {
      nearPoints.push_back(near(p));
      withFitted.push_back(fitted(p));
      withTrueSize.push_back(trueSize(p));
    }
    r.contourLoss = nearKnotLoss(contours, withFitted, nearPoints);
    r.contourLossAtTrueSize = nearKnotLoss(contours, withTrueSize, nearPoints);
    r.detectedContours = contourErrors(truth, contours, near);
    out.knots.push_back(r);
  }
  return out;
}

}  // namespace kerf::testing
