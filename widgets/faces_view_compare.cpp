// FacesView's compare displays: Split (photo | model at a draggable line) and Difference (heat map and
// legend). See faces_view.hpp.
#include <QLinearGradient>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "face_difference.hpp"
#include "face_difference_maps.hpp"
#include "faces_view.hpp"

namespace kerf {

namespace {

constexpr qreal kSplitGrabPx = 6;  // how near the line the left button takes it
const QColor kTagBackground(0, 0, 0, 165);

}  // namespace

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

  // The line, with a grip half-way down where it can be taken.
  const QRectF visible = target.intersected(rect());
  if (x < visible.left() - 1 || x > visible.right() + 1) return;
  painter.save();
  painter.setPen(QPen(QColor(0, 0, 0, 140), 3));
  painter.drawLine(QPointF(x, visible.top()), QPointF(x, visible.bottom()));
  painter.setPen(QPen(Qt::white, 1));
  painter.drawLine(QPointF(x, visible.top()), QPointF(x, visible.bottom()));
  const qreal y = visible.center().y(), h = std::clamp(visible.height() * 0.12, 10.0, 22.0), w = h * 0.9;
  painter.setPen(QPen(QColor(0, 0, 0, 160), 1));
  painter.setBrush(Qt::white);
  painter.drawRoundedRect(QRectF(x - w / 2, y - h / 2, w, h), 3, 3);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(60, 60, 60));
  const qreal a = w * 0.3;
  painter.drawPolygon(QPolygonF({QPointF(x - 1.5, y - a), QPointF(x - 1.5 - a, y), QPointF(x - 1.5, y + a)}));
  painter.drawPolygon(QPolygonF({QPointF(x + 1.5, y - a), QPointF(x + 1.5 + a, y), QPointF(x + 1.5, y + a)}));
  painter.restore();
  if (target.width() >= 140) {  // which side is which, where there is room
    if (x - target.left() > 50) drawTag(painter, left, tr("photo"), Qt::AlignBottom | Qt::AlignRight);
    if (target.right() - x > 50) drawTag(painter, right, tr("model"), Qt::AlignBottom | Qt::AlignLeft);
  }
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
  painter.save();
  QFont font = painter.font();
  font.setPixelSize(static_cast<int>(std::clamp(face.height() * 0.06, 10.0, 13.0)));
  font.setBold(false);
  painter.setFont(font);
  const QFontMetricsF metrics(font);
  const QSizeF size(metrics.horizontalAdvance(text) + 10, metrics.height() + 4);
  const qreal margin = 4;
  const qreal x = corner & Qt::AlignRight ? face.right() - margin - size.width() : face.left() + margin;
  const qreal y = corner & Qt::AlignBottom ? face.bottom() - margin - size.height() : face.top() + margin;
  const QRectF box(QPointF(x, y), size);
  painter.setClipRect(face.intersected(rect()));
  painter.setPen(Qt::NoPen);
  painter.setBrush(kTagBackground);
  painter.drawRoundedRect(box, 3, 3);
  painter.setPen(QColor(235, 235, 235));
  painter.drawText(box, Qt::AlignCenter, text);
  painter.restore();
}

void FacesView::drawDifferenceLegend(QPainter& painter) const {
  // In the view's bottom-right corner (at fit: the empty corner below E and F), whatever the zoom.
  painter.save();
  QFont font = painter.font();
  font.setPixelSize(11);
  font.setBold(false);
  painter.setFont(font);
  const QFontMetricsF metrics(font);
  const QString hueNote = tr("white: another hue at the same lightness");
  const qreal pad = 7, line = metrics.height(), barH = 10;
  const qreal w = std::max<qreal>(236, metrics.horizontalAdvance(hueNote) + 2 * pad + 4);
  const qreal h = pad + line + 3 + barH + 2 + line + line + pad;
  const QRectF box(width() - w - 10, height() - h - 10, w, h);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(20, 20, 22, 215));
  painter.drawRoundedRect(box, 5, 5);

  const QRectF inner = box.adjusted(pad, pad, -pad, -pad);
  painter.setPen(QColor(235, 235, 235));
  QFont bold = font;
  bold.setBold(true);
  painter.setFont(bold);
  painter.drawText(QRectF(inner.left(), inner.top(), inner.width(), line), Qt::AlignLeft | Qt::AlignVCenter,
                   tr("Model against photo"));
  painter.setFont(font);

  // The scale of pure lightness differences: darker .. same .. lighter, full colour at both ends.
  const QRectF bar(inner.left(), inner.top() + line + 3, inner.width(), barH);
  QImage scale(2 * kDifferenceFullScale + 1, 1, QImage::Format_RGB32);
  for (int i = -kDifferenceFullScale; i <= kDifferenceFullScale; ++i)
    scale.setPixel(i + kDifferenceFullScale, 0, differenceColour(std::abs(i), i));
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(bar, scale);
  painter.setPen(QColor(120, 120, 120));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(bar);

  const QRectF labels(inner.left(), bar.bottom() + 2, inner.width(), line);
  painter.setPen(QColor(215, 215, 215));
  painter.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, tr("model darker"));
  painter.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter, tr("same"));
  painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, tr("model lighter"));
  painter.setPen(QColor(170, 170, 170));
  painter.drawText(labels.translated(0, line), Qt::AlignLeft | Qt::AlignVCenter, hueNote);
  painter.restore();
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
