#pragma once
// The Rings work (docs/editor.md): Detect Rings runs the ring detector on every face photo (a job); the
// ring-localization images and contours are kept here, not in the project file, and the contours become
// the document's detected ring traces (one undo step), drawn over the faces. Fit Growth Field fits the
// growth field to the traces and the detected images (or to the sample folder's own X_arl*.png when
// nothing was detected) and applies it as one undo step, with the other pith candidate of an ambiguous
// fit one action away. The ring-tracing tools' edits and the Mokume export of the annotations
// (rings_traces.cpp).
#include <QString>
#include <memory>
#include <string>

#include "editor_controller.hpp"
#include "fit_job.hpp"

class QAction;
class QTimer;

namespace kerf {

class AnnotationLayer;
class FacesController;
class FacesView;

class RingsController : public EditorController {
  Q_OBJECT

 public:
  RingsController(const EditorContext& context, FacesController* faces, FacesView* facesView,
                  AnnotationLayer* annotationLayer);

  // The actions whose state follows the rings (made with the window's menus).
  struct Actions {
    QAction* showContours;
    QAction* showResiduals;
    QAction* otherPith;
    QAction* exportAnnotations;
  };
  void setActions(const Actions& actions);

  void detectRings();
  // Which ring detector Detect Rings and Reconstruct use: "learned" or "classical" (fit_job.hpp).
  void setDetector(const std::string& name) { detector_ = name; }
  const std::string& detector() const { return detector_; }
  void fitGrowthField();
  // After an ambiguous fit (Mokume B.1): swaps the field for the one around the other pith candidate.
  void useOtherPithCandidate();
  // How sure the last fit is (rings_uncertainty.cpp): the field refitted on resampled ring contours in a
  // background job; it lands in the document only while the
  // field is still the fit's. Started after every fit (after Reconstruct's last stage when it ran one).
  void estimateUncertainty();
  bool isEstimatingUncertainty() const;
  void cancelUncertainty();
  // The knots follow their marks (rings_knot_refit.cpp; issue 19 item 1): after the user moves, releases
  // or re-weighs a knot mark on the last fit's field, the knot stage alone runs again in the background
  // (a second or two) and its knots replace the field's as one undo step. Called a moment after the edit.
  void refitKnots();
  bool isRefittingKnots() const;
  // The annotations as Mokume images into `folder` (asked for when empty). Returns false (with a
  // message) when nothing was written.
  bool exportAnnotations(QString folder = {});

  // Null before a detection, and after the photos change.
  std::shared_ptr<const RingDetection> ringDetection() const { return ringDetection_; }
  std::shared_ptr<const GrowthFitResult> lastFit() const { return lastFit_; }
  bool isBusy() const;  // detecting or fitting
  bool isFitting() const;

  // Results that have landed (from their own action or from Reconstruct), applied as one undo step each;
  // false (with a message) when the result is not valid.
  void showRingDetection(std::shared_ptr<const RingDetection> detection);
  bool applyFit(std::shared_ptr<const GrowthFitResult> fit);
  // The field being fitted, on every view before it is applied.
  void showFitPreview(const WoodParameters& params, const GrowthRates& rates);

 signals:
  // Detect Rings / Fit Growth Field finished and their result is shown / applied.
  void ringsDetected();
  void growthFieldFitted();
  void fitPreviewed();
  // How sure the fit is has been estimated and is the document's (Document::ringUncertainty).
  void fitUncertaintyEstimated();
  // The knots were fitted again to their edited marks and are the document's.
  void knotsRefitted();
  // Either of them failed (the message is also in the log and a message box) or was cancelled.
  void ringJobFailed(const QString& message);

 private:
  void fail(const QString& message);
  void clearRingDetection();
  void ringJobEnded(int id, const QString& message);
  void showFitResiduals(const GrowthFitResult& fit);
  void applyDetectedTraces(const RingDetection& detection);  // rings_traces.cpp
  void annotationsChanged();
  void uncertaintyJobEnded(int id, const QString& message);  // rings_uncertainty.cpp
  void knotRefitJobEnded(int id, const QString& message);    // rings_knot_refit.cpp

  FacesController* faces_;
  FacesView* facesView_;
  AnnotationLayer* annotationLayer_;
  Actions actions_{};
  int ringJob_ = 0, fitJob_ = 0, uncertaintyJob_ = 0, knotRefitJob_ = 0;
  QTimer* knotRefitTimer_ = nullptr;  // a refit starts when the marks have been still a moment
  std::shared_ptr<const RingDetection> ringDetection_;
  std::string detector_ = kDefaultEditorRingDetector;
  std::shared_ptr<const GrowthFitResult> lastFit_;  // for the other pith candidate
};

}  // namespace kerf
