#pragma once
// A photo with four draggable corner handles: where the user marks the corners of one block face on
// their own photo (core/io/face_photo_rectify.hpp). The photo is shown whole (fitted, aspect kept);
// corners are kept in the *source* photo's continuous pixel coordinates (docs/coordinates.md: a pixel's
// centre at +0.5), so the widget can show a reduced copy of a big phone photo while the corners stay
// exact for the full-size rectification.
//
// Handles are numbered 1..4 in the order rectification expects (clockwise, starting at the corner that
// becomes the top-left before turning). While a handle is dragged, or hovered, a loupe shows the photo
// around it magnified with a cross-hair, so a corner can be placed on the arris to a pixel. Arrow keys
// nudge the selected handle by one photo pixel (Shift: 10), keys 1..4 select a handle. Each side of the
// outline can carry a label (e.g. the neighbouring face across that edge).
//
// Patch mode (setPatchMode): a left-drag draws a rectangle, reported by patchPicked() in photo
// pixels: the neutral patch for white balance. The last patch stays drawn (setPatch).
#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <array>
#include <optional>

namespace kerf {

class CornerPickerView : public QWidget {
  Q_OBJECT

 public:
  explicit CornerPickerView(QWidget* parent = nullptr);

  // `image` shows a photo of `sourceSize` pixels (it may be smaller: a preview). A null image clears.
  void setImage(const QImage& image, QSize sourceSize);
  QSize sourceSize() const { return sourceSize_; }
  bool hasImage() const { return !image_.isNull(); }

  void setCorners(const std::array<QPointF, 4>& corners);  // photo pixels; emits nothing
  const std::array<QPointF, 4>& corners() const { return corners_; }
  // Labels drawn at the middle of each side: side k runs from corner k to corner k + 1.
  void setSideLabels(const std::array<QString, 4>& labels);
  // The side drawn thicker (the one that becomes the top of the face), or -1.
  void setHighlightedSide(int side);

  void setPatchMode(bool on);
  bool patchMode() const { return patchMode_; }
  void setPatch(std::optional<QRectF> patch);  // photo pixels
  std::optional<QRectF> patch() const { return patch_; }

  int selectedCorner() const { return selected_; }
  void setSelectedCorner(int corner);

  // Geometry, for tests: widget position <-> photo pixels.
  QPointF widgetToPhoto(QPointF widgetPos) const;
  QPointF photoToWidget(QPointF photoPos) const;
  // The loupe's rectangle while it is shown (null otherwise).
  QRectF loupeRect() const;

  QSize sizeHint() const override { return {720, 540}; }
  QSize minimumSizeHint() const override { return {240, 180}; }

 signals:
  // A handle moved (by mouse or keyboard); finished on release (or after a key press).
  void cornersChanged(bool finished);
  void patchPicked(QRectF patch);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  QRectF imageRect() const;  // where the photo is drawn, widget pixels
  int handleAt(QPointF widgetPos) const;
  void drawLoupe(class QPainter& painter, QPointF photoPos) const;
  QPointF clampToPhoto(QPointF photoPos) const;

  QImage image_;
  QSize sourceSize_;
  std::array<QPointF, 4> corners_{};
  std::array<QString, 4> sideLabels_;
  int highlightedSide_ = 0;
  int selected_ = 0;
  int dragging_ = -1;
  int hovered_ = -1;
  QPointF dragOffset_;  // photo pixels: handle minus press position
  bool patchMode_ = false;
  std::optional<QRectF> patch_;
  std::optional<QPointF> patchStart_;
  QPointF patchEnd_;
};

}  // namespace kerf
