#pragma once
// Cut ▸ Align Cut Photo: where the photo of the sawn surface lies on the cut. The four handles of the
// photo import's corner picker (widgets/corner_picker_view.hpp) go onto the corners of the cut's
// rectangle on the photo, clockwise, and a quarter turn and mirror bring the photo into the cut panel's
// orientation (io/cut_photo.hpp). The side drawn thicker becomes the top of the cut as the panel shows it.
#include <QDialog>
#include <QImage>

#include "io/face_photo_rectify.hpp"

class QLabel;
class QToolButton;

namespace kerf {

class CornerPickerView;

class CutPhotoDialog : public QDialog {
  Q_OBJECT

 public:
  // `photo`: the photo's pixels (full size; corners are in its pixels); `setup`: the alignment so far.
  CutPhotoDialog(const QImage& photo, const FacePhotoSetup& setup, QWidget* parent = nullptr);

  const FacePhotoSetup& setup() const { return setup_; }
  void setRotation(int degrees);
  void setFlip(bool flip);
  void useWholePhoto();

 private:
  void cornersEdited();
  void showSetup();

  FacePhotoSetup setup_;
  QSize photoSize_;
  CornerPickerView* picker_;
  QToolButton* flipButton_;
  QLabel* problem_;
};

}  // namespace kerf
