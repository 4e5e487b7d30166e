#pragma once
// File > Import Photos: turn the user's own photos of a block into the six face images.
//
// For each photo: which face it shows (guessed from a file name starting "A_", "b-", ..), the face's four
// corners on the photo (CornerPickerView, with a loupe), a quarter turn and mirror into the face's
// orientation, and white balance (none, automatic, or from a neutral patch picked on the photo). For the
// block: its size in mm (a cuboid is fine) and the px/mm of the written faces. The unfolded cross on the
// right shows the rectified faces live (rectified from a reduced copy of each photo, so dragging a corner
// stays smooth); faces no photo is assigned to keep the document's photo.
//
// Photos load in the background (photosLoaded() when all have). OK checks everything (duplicate faces,
// corners that do not make a face, no folder) and stays open with the problem shown otherwise; the
// caller then runs plan() through startPhotoImport (photo_import.hpp), which writes the faces at full
// size off the GUI thread and applies them as one undo step.
#include <QDialog>
#include <QFutureWatcher>
#include <QImage>
#include <QStringList>
#include <QTimer>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "io/image.hpp"
#include "photo_import.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QToolButton;

namespace kerf {

class CornerPickerView;
class FacesView;

enum class WhiteBalanceMode { None, Auto, Patch };

class PhotoImportDialog : public QDialog {
  Q_OBJECT

 public:
  // `block` and `currentPhotos`: the document's, shown for faces that get no new photo.
  PhotoImportDialog(const Block& block, const std::array<QImage, 6>& currentPhotos,
                    QWidget* parent = nullptr);
  ~PhotoImportDialog() override;

  // Adds photos; they load in the background. Unreadable ones are dropped with a message.
  void addPhotos(const QStringList& paths);
  bool isLoading() const;
  int photoCount() const { return static_cast<int>(photos_.size()); }
  QString photoPath(int index) const;
  QSize photoSize(int index) const;  // full size, pixels
  void removePhoto(int index);
  int currentPhoto() const { return current_; }
  void setCurrentPhoto(int index);

  // Per photo (index into the list). Corners are in full-size photo pixels (face_photo_rectify.hpp).
  std::optional<FaceId> face(int index) const;
  void setFace(int index, std::optional<FaceId> face);
  FacePhotoSetup setup(int index) const;
  void setCorners(int index, const std::array<glm::vec2, 4>& corners);
  void setRotation(int index, int degrees);
  void setFlip(int index, bool flip);
  WhiteBalanceMode whiteBalanceMode(int index) const;
  void setWhiteBalance(int index, WhiteBalanceMode mode, std::optional<QRectF> patch = std::nullopt);

  glm::vec3 blockSize() const;
  void setBlockSize(glm::vec3 sizeMm);
  float pxPerMm() const;
  void setPxPerMm(float pxPerMm);
  QString outputFolder() const;
  void setOutputFolder(const QString& folder);
  // While false (tests), OK replaces existing face files without asking.
  void setAskBeforeReplacing(bool ask) { askBeforeReplacing_ = ask; }

  // What OK hands over; InputError (with a message for the user) when something is not ready.
  PhotoImportPlan plan() const;
  // The rectified preview of each face as the cross shows it (null where no photo is assigned).
  const std::array<QImage, 6>& previewFaces() const { return previews_; }
  // Problems the preview ran into (bad corners, a white-balance patch that says nothing), "" if none.
  QString problems() const;
  QString lastError() const { return lastError_; }

  CornerPickerView* cornerPicker() const { return picker_; }
  FacesView* previewView() const { return preview_; }

  void accept() override;

 signals:
  void photosLoaded();  // every photo added so far has loaded (or failed)
  void previewUpdated();

 private:
  struct Photo;
  struct Loaded;
  void buildUi();
  void photoLoaded(Photo* photo, const Loaded& loaded);
  void showCurrent();
  void updateList();
  void updatePicker();
  void updateInfo();
  void schedulePreview(bool all);
  void updatePreviews();
  void rectifyPreview(Photo& photo);
  void chooseFolder();
  void choosePhotos();
  void cornersEdited(bool finished);
  void patchPicked(QRectF patch);
  Photo* photo(int index) const;
  std::optional<FaceId> firstFreeFace() const;
  std::array<glm::vec2, 4> defaultCorners(const Photo& photo) const;
  glm::vec2 faceMm(FaceId face) const;

  std::vector<std::unique_ptr<Photo>> photos_;
  std::array<QImage, 6> currentPhotos_, previews_;
  int current_ = -1;
  bool askBeforeReplacing_ = true;
  bool folderChosen_ = false;
  bool updating_ = false;  // controls being filled from a photo: their signals are ignored
  bool previewAll_ = false;
  QString lastError_;
  QTimer previewTimer_;

  QListWidget* list_ = nullptr;
  CornerPickerView* picker_ = nullptr;
  FacesView* preview_ = nullptr;
  QComboBox* faceCombo_ = nullptr;
  QLabel* turnLabel_ = nullptr;
  QToolButton* flipButton_ = nullptr;
  QComboBox* balanceCombo_ = nullptr;
  QToolButton* pickPatchButton_ = nullptr;
  std::array<QDoubleSpinBox*, 3> sizeBoxes_{};
  QDoubleSpinBox* pxPerMmBox_ = nullptr;
  QLineEdit* folderEdit_ = nullptr;
  QLabel* info_ = nullptr;
  QLabel* hint_ = nullptr;
  QPushButton* removeButton_ = nullptr;
  QPushButton* okButton_ = nullptr;
  std::vector<QWidget*> photoControls_;  // enabled only while a photo is shown
};

}  // namespace kerf
