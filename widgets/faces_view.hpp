#pragma once
// The six faces of a block laid out as the unfolded Mokume cross (B above A, D below, C left, E and F
// to the right; see kerf::crossSlot), each labelled with its letter, scaled to fit with the block's
// proportions kept. Faces are placed by their size in mm, so photos of any resolution line up.
#include <QImage>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <array>

#include "geometry/block.hpp"

namespace kerf {

class FacesView : public QWidget {
  Q_OBJECT

 public:
  explicit FacesView(QWidget* parent = nullptr);

  // Faces in A..F order; a null image leaves its slot as an empty outline.
  void setFaces(const std::array<QImage, 6>& faces, const Block& block);
  void clear();
  const std::array<QImage, 6>& faces() const { return faces_; }
  const Block& block() const { return block_; }
  bool hasFaces() const;

  // Shown centred while there are no faces ("Rendering faces…").
  void setPlaceholderText(const QString& text);

  // A title and a line of detail, drawn in the empty corner right of B ("Photos", "Ctrl+T: …").
  void setCaption(const QString& title, const QString& detail = {});

  // Where face `face` is drawn, in widget pixels (for tests and later overlays).
  QRectF faceRect(FaceId face) const;

  QSize sizeHint() const override { return {960, 720}; }
  QSize minimumSizeHint() const override { return {240, 180}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void drawLabel(class QPainter& painter, const QRectF& rect, FaceId face, qreal side) const;
  void drawCaption(QPainter& painter) const;

  std::array<QImage, 6> faces_;
  Block block_;
  QString placeholder_;
  QString captionTitle_, captionDetail_;
};

}  // namespace kerf
