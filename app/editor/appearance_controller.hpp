#pragma once
// The photo-true appearance in the editor (issue 17): Texture ▸ Photo-true Appearance makes every surface
// the user sees (the faces, the 3D block and its cut, the cut panel) of the block's own photos, re-grown
// along the fitted growth field (appearance/photo_true_appearance.hpp), instead of the procedural wood.
// The project stores the choice (Project::appearance, as `kerf-cli texture --appearance photo`).
//
// Progressive: the procedural wood shows at once after every edit (the views draw it live); the photo-true
// surfaces replace it as they land, the cut panel's first (what a woodworker reads), then the faces one by
// one. Each picture belongs to the model (and plane) it was made of, so a stale one never shows. The photos'
// guidance (the expensive part that does not depend on the surface) is made once per model and photos and
// kept; the last cuts are kept too, so going back to a plane is instant. Held-out faces
// (Project::heldOutFaces) are never used. The work runs in the background; a newer edit cancels it.
#include <QAction>
#include <QTimer>
#include <list>
#include <memory>

#include "document_jobs.hpp"
#include "editor_controller.hpp"
#include "surface_image.hpp"

namespace kerf {

class CutView;
class FacesController;
class Viewport3D;
struct PhotoTrueSurfaces;

class AppearanceController : public EditorController {
  Q_OBJECT

 public:
  AppearanceController(const EditorContext& context, RenderSettings settings, FacesController* faces,
                       CutView* cutView, Viewport3D* viewport);
  ~AppearanceController() override;

  // Texture ▸ Photo-true Appearance (checkable, Ctrl+Shift+P): enabled with photos, checked from the
  // document.
  QAction* photoTrueAction() const { return photoTrueAction_; }
  // Whether photo-true work is running or about to start.
  bool isWorking() const;
  // How long the editor waits after the last edit before making the photo-true surfaces (ms).
  static constexpr int kSettleMs = 300;

 signals:
  void facesMade();  // the document model's six photo-true faces are shown
  void cutMade();    // the photo-true cut of the document's plane is shown

 private:
  void documentChanged();
  void updateAction();
  void startFaces();
  void startCut();
  void showCut(const CutAppearance& cut);
  bool wanted() const;

  RenderSettings settings_;
  FacesController* faces_;
  CutView* cutView_;
  Viewport3D* viewport_;
  QAction* photoTrueAction_;
  QTimer settle_, cutSettle_;
  std::shared_ptr<const PhotoTrueSurfaces> source_;  // of the document's model, once made
  int facesJob_ = 0, cutJob_ = 0;
  std::list<CutAppearance> cuts_;  // the latest first
  static constexpr std::size_t kKeptCuts = 6;
};

}  // namespace kerf
