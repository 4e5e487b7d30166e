#pragma once
// The document's wood on the views: the faces rendered in the background (the model's, or the board's
// while a log is open), progressively and latest wins; what the faces show (photos, model, blend, split,
// difference) and the controls that choose it; previews of a field or texture being computed on the faces,
// the 3D view and the cut. Also whether a document is open at all (nothing renders before one is).
#include <QImage>
#include <array>
#include <memory>

#include "document_jobs.hpp"
#include "editor_controller.hpp"

class QAction;
class QActionGroup;
class QSlider;

namespace kerf {

class CutView;
class FacesView;
class Viewport3D;
class WoodModel;

class FacesController : public EditorController {
  Q_OBJECT

 public:
  FacesController(const EditorContext& context, RenderSettings settings, FacesView* facesView,
                  Viewport3D* viewport, CutView* cutView);

  // The Photos .. Difference actions (their data: the FaceDisplay), View ▸ Show Model/Photos and the slider
  // of Blend (opacity) and Split (where the line lies).
  void setDisplayControls(QActionGroup* displays, QAction* toggleView, QSlider* slider);

  RenderSettings settings() const { return settings_; }
  bool hasDocument() const { return hasDocument_; }
  // A document is opening (or a log becomes one): documentReady follows its first full rendering.
  // `freshView`: the faces forget the previous document's renderings and what the user chose to show.
  void beginDocument(bool freshView);
  // Said on the faces while the first document opens.
  void showPlaceholder(const QString& text);

  // The document's model on every view (after an edit, or back from a preview).
  void showDocumentModel();
  void showRingUncertainty();  // the document's, over the cut (when it belongs to its field)
  // A model that is not the document's yet (a fit or texture under way) on every view.
  void showPreview(std::shared_ptr<const WoodModel> model);
  void renderFaces();

  // The faces' own appearance (photo-true, issue 17) for `forModel`: shown as the model's faces (and on
  // the 3D block) while that model is the one shown; a newer model shows its own rendering until its
  // pictures come. Null model: none.
  void setAppearanceFaces(std::shared_ptr<const WoodModel> forModel, const std::array<QImage, 6>& faces);
  // Whether the faces view shows the appearance pictures now.
  bool showsAppearanceFaces() const;

  bool showingPhotos() const;
  bool displayChosenByUser() const { return displayChosenByUser_; }
  // The user (or Reconstruct for them) chose what the faces show; it stays until the next document.
  void chooseDisplay(int display);
  void toggleView();
  void updateFacesView();

 signals:
  void facesRendered();
  void facesPreviewed();
  void documentReady();

 private:
  void renderFacesOf(std::shared_ptr<const WoodModel> model);
  void renderBoardFaces();
  void showRenderings(const QVariant& faces, bool final);
  void setFaceDisplay(int display);
  void updateFaceSlider();

  RenderSettings settings_;
  FacesView* facesView_;
  Viewport3D* viewport_;
  CutView* cutView_;
  QActionGroup* displays_ = nullptr;
  QAction* toggleViewAction_ = nullptr;
  QSlider* slider_ = nullptr;
  bool hasDocument_ = false;
  bool documentReadyPending_ = false;
  std::array<QImage, 6> renderings_;
  std::shared_ptr<const WoodModel> renderedModel_;  // the model renderings_ are (being) made of
  std::shared_ptr<const WoodModel> appearanceModel_;
  std::array<QImage, 6> appearanceFaces_;
  int renderJob_ = 0;
  int displayMode_ = 0;  // FaceDisplay as int
  bool displayChosenByUser_ = false;
};

}  // namespace kerf
