#pragma once
// The photo of a real cut (docs/editor.md, "Comparing a photo of the cut"): Load Cut Photo puts a photo
// of the sawn surface on the cut of the plane shown, Align Cut Photo fits its corners, turn and mirror to
// the cut (cut_photo_dialog.hpp), Remove Cut Photo takes it away; each is one undo step and the photo is
// saved with the project (io/cut_photo.hpp). The cut panel then shows the model's cut, the photo, photo |
// model at a line, or their difference (CutView's CutDisplay), against the procedural wood or the
// photo-true cut, whichever the panel shows.
//
// The photo is rectified onto the cut, and the model's cut rendered for the difference, on the background
// pool: the GUI thread never waits. A newer request makes older results be dropped.
#include <QImage>
#include <QString>
#include <array>
#include <glm/vec2.hpp>
#include <optional>

#include "cut_view.hpp"
#include "editor_controller.hpp"
#include "io/cut_photo.hpp"

class QAction;
class QActionGroup;

namespace kerf {

class CutPhotoController : public EditorController {
  Q_OBJECT

 public:
  CutPhotoController(const EditorContext& context, CutView* cutView);

  QAction* loadAction() const { return loadAction_; }
  QAction* alignAction() const { return alignAction_; }
  QAction* removeAction() const { return removeAction_; }
  QActionGroup* displayGroup() const { return displayGroup_; }

  // Reads the photo in the background and puts it, framed whole, on the cut of the plane shown (one undo
  // step). A missing or unreadable file gives an error naming it.
  void loadCutPhoto(const QString& path);
  void chooseCutPhoto();   // a file dialog, then loadCutPhoto
  void chooseAlignment();  // the alignment dialog, then setAlignment
  // The photo's corners (photo pixels, clockwise from the cut's top-left), turn and mirror (one undo step).
  // InputError (nothing pushed) for corners that make no four-sided surface.
  void setAlignment(const std::array<glm::vec2, 4>& corners, int rotationDegrees, bool flip);
  void removeCutPhoto();
  void setDisplay(CutDisplay display);
  // Whether the cut panel's picture is of the document's cut photo as it is now (its file and alignment).
  bool showsDocumentPhoto() const;
  // The photo-true cut landed, or something else the model's side of the difference depends on changed.
  void modelSideChanged();

 signals:
  void cutPhotoShown();    // a rectified photo is on the cut panel (or none is, after removing it)
  void differenceReady();  // the heat map of the model and appearance shown is on the cut panel

 private:
  void photoChanged();
  void restoreImage();
  void startRectify();
  void startDifference();
  void updateActions();

  CutView* cutView_;
  QAction* loadAction_;
  QAction* alignAction_;
  QAction* removeAction_;
  QActionGroup* displayGroup_;
  int rectifyGeneration_ = 0, differenceGeneration_ = 0;
  QString restoring_;  // the saved photo being read after opening ("" when none)
  float pxPerMm_ = 0.0f;
  std::optional<CutPhoto> shownPhoto_;  // what the panel's picture was rectified from
};

}  // namespace kerf
