#pragma once
// The editor's ring work, run off the GUI thread as JobRunner jobs: ring detection on the face photos
// (the learned or the classical detector, as `kerf-cli detect`) and the growth-field fit on ring-localization
// images (pith axis, ring width and phase, then the growth rates: fitGrowthFieldToSample, the pipeline of
// `kerf-cli fit`, fit/growth_field_fit.hpp). Self-contained functions of values: no QObject, no shared state.
#include <QImage>
#include <QPolygonF>
#include <QSize>
#include <QString>
#include <QStringList>
#include <array>
#include <filesystem>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "field/ring_uncertainty.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/iso_contours.hpp"
#include "geometry/block.hpp"
#include "geometry/face_set.hpp"
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"
#include "util/progress.hpp"
#include "util/report_line.hpp"

namespace kerf {

// What Detect Rings found: per face A..F, the ring-localization image (8-bit, the photo's size; empty
// where the face has no photo) and its contours (pixel indices, docs/rings.md).
struct RingDetection {
  std::array<GrayImage8, 6> arl;
  std::array<std::vector<std::vector<glm::ivec2>>, 6> contours;
  std::array<double, 6> seconds{};
  int facesDetected = 0;
  std::string detector;  // which detector found them ("learned", "classical")
  int contourCount() const;
  bool empty() const { return facesDetected == 0; }
};

// The ring detector the editor uses unless the user picks the other (Rings ▸ Learned Ring Detector).
inline constexpr const char* kDefaultEditorRingDetector = "classical";

// Runs the named ring detector ("learned" or "classical", rings/learned_ring_detector.hpp) on every face
// photo (A..F; null photos are skipped), at the resolution given by the block (photo width / face width).
// Throws InputError without any photo, Cancelled on request.
RingDetection detectRings(const std::array<QImage, 6>& photos, const Block& block,
                          const std::string& detector, const Progress& progress = {});

// The detected contours as ring traces of the document (face mm; origin Detected), for
// replaceDetectedTraces: what Detect Rings adds and Fit Growth Field then fits.
std::vector<RingTrace> detectedRingTraces(const RingDetection& detection, const Block& block);

// The contours as polylines in continuous image coordinates (pixel centres at x + 0.5, y + 0.5), for
// FacesView::setOverlayPolylines, with the sizes of the images they belong to.
std::array<std::vector<QPolygonF>, 6> contourPolylines(const RingDetection& detection);
std::array<QSize, 6> detectionSizes(const RingDetection& detection);

// The ring-localization images a sample folder holds (X_arl-unet.png, else the first X_arl*.png by
// name), as `kerf-cli fit` reads them; faces without one are empty.
std::array<GrayImage8, 6> readFolderRingImages(const std::filesystem::path& folder);

// One fitted contour, for the residual overlay: face mm points (rings/annotations.hpp) and how far
// they stray from their ring, in ring spacings.
struct FittedContour {
  FaceId face = FaceId::A;
  std::vector<glm::vec2> pointsMm;
  double residualRings = 0;
};

struct GrowthFitResult {
  WoodParameters params;  // the input parameters with growth.pith_*, ring_width, ring_offset replaced
  GrowthRates rates;
  std::vector<BlockKnot> knots;           // fitted from the knot marks (Mokume Sec. 5.2.4)
  std::vector<ReportLine> report;         // lines for the log: contours, loss, O, V, ambiguity, timings
  std::vector<KnotOutline> knotOutlines;  // each knot mark's edge on its photo (issue 19 item 2)
  bool ambiguous = false;
  double lossRings = 0;  // final iso-contour loss of the saved field, in ring spacings
  std::vector<FittedContour> contours;
  // The field around the mirrored pith, when the pith side was ambiguous and it could be fitted.
  struct Alternative {
    WoodParameters params;
    GrowthRates rates;
    double lossRings = 0;
    std::vector<BlockKnot> knots;
  };
  std::optional<Alternative> alternative;
  // What the fit was given (inputs and options, without the preview), so that how sure it is can be
  // estimated afterwards from the same evidence (estimateFitUncertainty).
  std::shared_ptr<const GrowthFieldFitInput> input;
  GrowthFieldFitOptions options;
};

// A field for the live preview while the fit runs (called from the fitting thread).
using GrowthFitPreview = std::function<void(const WoodParameters&, const GrowthRates&)>;

// The growth-field fit of `kerf-cli fit` on the given ring-localization images and ring traces, with the
// anatomical prior from the face photos where there are any (null images: none). Throws InputError when
// there are too few contours to fit (fewer than kMinFitContours, or on fewer than two faces), Cancelled
// on request. Nothing of the held-out faces (Project::heldOutFaces) is used: fit/held_out_faces.hpp.
GrowthFitResult fitGrowthField(const std::array<GrayImage8, 6>& images, const Block& block,
                               const WoodParameters& current, const std::array<QImage, 6>& photos = {},
                               const Progress& progress = {}, const std::vector<RingTrace>& traces = {},
                               const GrowthFitPreview& preview = {},
                               const std::vector<KnotMark>& knotMarks = {}, const FaceSet& heldOut = {});

// How sure `fit` is inside the block (fit/ring_uncertainty_fit.hpp): the field refitted on resampled
// contours of the fit's own input. Minutes on a large block; Cancelled on request, InputError when the fit
// kept no input or too few refits succeed.
RingUncertainty estimateFitUncertainty(const GrowthFitResult& fit, const Block& block,
                                       const Progress& progress = {});

}  // namespace kerf
