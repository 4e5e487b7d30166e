// FacesView's compare displays: Split (photo | model at a draggable line) and Difference (heat map and
// legend). See faces_view.hpp.
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "compare_overlay.hpp"
#include "face_difference_maps.hpp"
#include "faces_view.hpp"

namespace kerf {

void FacesView::setSplitPosition(double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (fraction == splitPosition_) return;
  splitPosition_ = fraction;
  emit splitPositionChanged(fraction);
  update();
}

const std::array<QImage, 6>& FacesView::differenceMaps() const {
  return differences_->maps();
}

bool FacesView::differenceUpToDate() const {
  return !differencesStale_ && differences_->upToDate();
}

void FacesView::requestDifferences() {
  if (display_ != FaceDisplay::Difference || !differencesStale_) return;
  differencesStale_ = false;
  differences_->request(photos_, renderings_);
}

// --- Drawing ----------------------------------------------------------------------------------------

void FacesView::drawCompareFace(QPainter& painter, const QRectF& target, FaceId face) const {
  const QImage& photo = photos_[faceIndex(face)];
  const QImage& model = renderings_[faceIndex(face)];
  if (photo.isNull() || model.isNull()) {  // nothing to compare with: what there is, and why
    if (!model.isNull()) drawFace(painter, target, model);
    if (!photo.isNull()) drawFace(painter, target, photo);
    drawTag(painter, target, photo.isNull() ? tr("model only · no photo") : tr("photo only · no model yet"),
            Qt::AlignBottom | Qt::AlignLeft);
    return;
  }
  if (display_ == FaceDisplay::Split)
    drawSplitFace(painter, target, photo, model);
  else
    drawDifferenceFace(painter, target, face);
}

void FacesView::drawSplitFace(QPainter& painter, const QRectF& target, const QImage& photo,
                              const QImage& model) const {
  // Both images are stretched over the whole face and clipped at the line, so the wood is continuous
  // across it wherever the model is right.
  const qreal x = std::round(target.left() + splitPosition_ * target.width());
  const QRectF left(target.topLeft(), QPointF(x, target.bottom()));
  const QRectF right(QPointF(x, target.top()), target.bottomRight());
  for (const auto& [side, image] : {std::pair{left, &photo}, std::pair{right, &model}}) {
    painter.save();
    painter.setClipRect(side, Qt::IntersectClip);
    drawFace(painter, target, *image);
    painter.restore();
  }

  // The line, with a grip half-way down where it can be taken, and which side is which.
  const QRectF visible = target.intersected(rect());
  drawSplitLine(painter, x, visible);
  drawSplitTags(painter, target, rect(), x);
}

void FacesView::drawDifferenceFace(QPainter& painter, const QRectF& target, FaceId face) const {
  const QImage& map = differences_->maps()[faceIndex(face)];
  if (!map.isNull()) {
    drawFace(painter, target, map);
    if (!differenceUpToDate()) drawTag(painter, target, tr("updating…"), Qt::AlignBottom | Qt::AlignLeft);
    return;
  }
  painter.save();
  painter.setOpacity(0.35);
  drawFace(painter, target, renderings_[faceIndex(face)]);
  painter.restore();
  drawTag(painter, target, tr("comparing…"), Qt::AlignBottom | Qt::AlignLeft);
}

void FacesView::drawTag(QPainter& painter, const QRectF& face, const QString& text,
                        Qt::Alignment corner) const {
  drawCompareTag(painter, face, rect(), text, corner);
}

// --- The split line under the mouse ------------------------------------------------------------------

std::optional<FaceId> FacesView::splitLineAt(QPointF pos) const {
  if (!comparing() || display_ != FaceDisplay::Split) return std::nullopt;
  for (FaceId face : kAllFaces) {
    if (photos_[faceIndex(face)].isNull() || renderings_[faceIndex(face)].isNull()) continue;
    const QRectF r = faceRect(face);
    const qreal x = r.left() + splitPosition_ * r.width();
    if (pos.y() >= r.top() && pos.y() <= r.bottom() && std::abs(pos.x() - x) <= kSplitGrabPx) return face;
  }
  return std::nullopt;
}

bool FacesView::splitMousePress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || spaceHeld_ || panning_) return false;
  splitDrag_ = splitLineAt(event->position());
  if (!splitDrag_) return false;
  event->accept();
  return true;
}

bool FacesView::splitMouseMove(QMouseEvent* event) {
  if (splitDrag_ && !(event->buttons() & Qt::LeftButton)) splitDrag_.reset();  // released elsewhere
  if (splitDrag_) {
    const QRectF r = faceRect(*splitDrag_);
    setSplitPosition((event->position().x() - r.left()) / r.width());
    event->accept();
    return true;
  }
  // The cursor says where the line can be taken; what it was is given back when it leaves.
  const bool over = !panning_ && !spaceHeld_ && splitLineAt(event->position()).has_value();
  if (over && !cursorBeforeSplit_) {
    cursorBeforeSplit_ = cursor();
    setCursor(Qt::SplitHCursor);
  } else if (!over && cursorBeforeSplit_) {
    setCursor(*cursorBeforeSplit_);
    cursorBeforeSplit_.reset();
  }
  return false;
}

bool FacesView::splitMouseRelease(QMouseEvent* event) {
  if (!splitDrag_ || event->button() != Qt::LeftButton) return false;
  splitDrag_.reset();
  event->accept();
  return true;
}

}  // namespace kerf
