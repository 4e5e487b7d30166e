#include "corner_picker_view.hpp"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

constexpr qreal kHandleRadius = 7.0;
constexpr qreal kHitRadius = 14.0;
constexpr qreal kLoupeSide = 168.0;
constexpr qreal kLoupeMagnification = 6.0;  // loupe pixels per pixel of the shown image

const QColor kOutline(255, 196, 0);
const QColor kTopSide(80, 200, 255);
const QColor kPatch(120, 255, 120);

}  // namespace

CornerPickerView::CornerPickerView(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void CornerPickerView::setImage(const QImage& image, QSize sourceSize) {
  image_ = image;
  sourceSize_ = image.isNull() ? QSize() : (sourceSize.isValid() ? sourceSize : image.size());
  dragging_ = hovered_ = -1;
  patchStart_.reset();
  update();
}

void CornerPickerView::setCorners(const std::array<QPointF, 4>& corners) {
  corners_ = corners;
  update();
}

void CornerPickerView::setSideLabels(const std::array<QString, 4>& labels) {
  sideLabels_ = labels;
  update();
}

void CornerPickerView::setHighlightedSide(int side) {
  highlightedSide_ = side;
  update();
}

void CornerPickerView::setPatchMode(bool on) {
  patchMode_ = on;
  patchStart_.reset();
  setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
  update();
}

void CornerPickerView::setPatch(std::optional<QRectF> patch) {
  patch_ = patch;
  update();
}

void CornerPickerView::setSelectedCorner(int corner) {
  selected_ = std::clamp(corner, 0, 3);
  update();
}

QRectF CornerPickerView::imageRect() const {
  if (!sourceSize_.isValid() || sourceSize_.isEmpty()) return {};
  const QRectF area = QRectF(rect()).adjusted(12, 12, -12, -12);
  const qreal scale = std::min(area.width() / sourceSize_.width(), area.height() / sourceSize_.height());
  const QSizeF size(sourceSize_.width() * scale, sourceSize_.height() * scale);
  return {area.center() - QPointF(size.width() / 2, size.height() / 2), size};
}

QPointF CornerPickerView::widgetToPhoto(QPointF p) const {
  const QRectF r = imageRect();
  if (r.isEmpty()) return {};
  return {(p.x() - r.left()) * sourceSize_.width() / r.width(),
          (p.y() - r.top()) * sourceSize_.height() / r.height()};
}

QPointF CornerPickerView::photoToWidget(QPointF p) const {
  const QRectF r = imageRect();
  if (r.isEmpty()) return {};
  return {r.left() + p.x() * r.width() / sourceSize_.width(),
          r.top() + p.y() * r.height() / sourceSize_.height()};
}

QPointF CornerPickerView::clampToPhoto(QPointF p) const {
  return {std::clamp<qreal>(p.x(), 0, sourceSize_.width()),
          std::clamp<qreal>(p.y(), 0, sourceSize_.height())};
}

int CornerPickerView::handleAt(QPointF widgetPos) const {
  if (!hasImage()) return -1;
  int best = -1;
  qreal bestDistance = kHitRadius;
  for (int k = 0; k < 4; ++k) {
    const qreal d = QLineF(photoToWidget(corners_[k]), widgetPos).length();
    if (d <= bestDistance) best = k, bestDistance = d;
  }
  return best;
}

QRectF CornerPickerView::loupeRect() const {
  const int shown = dragging_ >= 0 ? dragging_ : hovered_;
  if (shown < 0 || !hasImage() || patchMode_) return {};
  // In the top-left corner, unless the handle is there; then in the top-right one.
  const QPointF handle = photoToWidget(corners_[shown]);
  const bool left = !(handle.x() < kLoupeSide + 40 && handle.y() < kLoupeSide + 40);
  return {left ? 8.0 : width() - kLoupeSide - 8.0, 8.0, kLoupeSide, kLoupeSide};
}

void CornerPickerView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(38, 38, 40));
  if (!hasImage()) {
    painter.setPen(QColor(190, 190, 190));
    painter.drawText(rect(), Qt::AlignCenter, tr("Add photos of the block's faces"));
    return;
  }
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.drawImage(imageRect(), image_);

  // The face's outline, its top side thicker, and what lies across each side.
  std::array<QPointF, 4> w;
  for (int k = 0; k < 4; ++k) w[k] = photoToWidget(corners_[k]);
  QPainterPath outline;
  outline.addPolygon(QPolygonF({w[0], w[1], w[2], w[3], w[0]}));
  painter.fillPath(outline, QColor(255, 196, 0, patchMode_ ? 0 : 28));
  for (int k = 0; k < 4; ++k) {
    painter.setPen(QPen(QColor(0, 0, 0, 160), k == highlightedSide_ ? 6 : 4));
    painter.drawLine(w[k], w[(k + 1) % 4]);
    painter.setPen(QPen(k == highlightedSide_ ? kTopSide : kOutline, k == highlightedSide_ ? 3 : 1.6));
    painter.drawLine(w[k], w[(k + 1) % 4]);
  }
  const QPointF centre = (w[0] + w[1] + w[2] + w[3]) / 4.0;
  QFont font = painter.font();
  font.setPixelSize(12);
  painter.setFont(font);
  for (int k = 0; k < 4; ++k) {
    if (sideLabels_[k].isEmpty()) continue;
    const QPointF middle = (w[k] + w[(k + 1) % 4]) / 2.0;
    QPointF out = middle - centre;
    const qreal length = std::hypot(out.x(), out.y());
    if (length > 0) out /= length;
    const QRectF box = painter.fontMetrics().boundingRect(sideLabels_[k]).adjusted(-5, -3, 5, 3);
    QRectF label(0, 0, box.width(), box.height());
    label.moveCenter(middle + out * (box.height() * 0.5 + 8));
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 170));
    painter.drawRoundedRect(label, 4, 4);
    painter.setPen(k == highlightedSide_ ? kTopSide : QColor(235, 235, 235));
    painter.drawText(label, Qt::AlignCenter, sideLabels_[k]);
  }

  // The neutral patch.
  std::optional<QRectF> patch = patch_;
  if (patchStart_) patch = QRectF(*patchStart_, patchEnd_).normalized();
  if (patch) {
    const QRectF r(photoToWidget(patch->topLeft()), photoToWidget(patch->bottomRight()));
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 180), 4));
    painter.drawRect(r);
    painter.setPen(QPen(kPatch, 2, Qt::DashLine));
    painter.drawRect(r);
  }

  // Handles, numbered in the order rectification takes them.
  font.setBold(true);
  font.setPixelSize(11);
  painter.setFont(font);
  for (int k = 0; k < 4; ++k) {
    const bool active = k == selected_ || k == dragging_;
    painter.setPen(QPen(Qt::black, 1.5));
    painter.setBrush(active ? kOutline : QColor(255, 255, 255, 200));
    painter.drawEllipse(w[k], kHandleRadius + (k == hovered_ ? 2 : 0),
                        kHandleRadius + (k == hovered_ ? 2 : 0));
    painter.drawText(QRectF(w[k] - QPointF(8, 8), QSizeF(16, 16)), Qt::AlignCenter, QString::number(k + 1));
  }

  const int shown = dragging_ >= 0 ? dragging_ : hovered_;
  if (shown >= 0 && !patchMode_) drawLoupe(painter, corners_[shown]);
}

void CornerPickerView::drawLoupe(QPainter& painter, QPointF photoPos) const {
  const QRectF target = loupeRect();
  if (target.isEmpty()) return;
  // Photo pixels across the loupe: kLoupeMagnification loupe pixels per pixel of the shown image.
  const qreal imagePerPhoto = static_cast<qreal>(image_.width()) / sourceSize_.width();
  const qreal span = kLoupeSide / kLoupeMagnification / imagePerPhoto;
  const QRectF source((photoPos.x() - span / 2) * imagePerPhoto, (photoPos.y() - span / 2) * imagePerPhoto,
                      span * imagePerPhoto, span * imagePerPhoto);
  const auto toLoupe = [&](QPointF p) { return target.center() + (p - photoPos) * (kLoupeSide / span); };
  painter.save();
  painter.setClipRect(target);
  painter.fillRect(target, QColor(20, 20, 20));
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);  // show the pixels as they are
  painter.drawImage(target, image_, source);
  painter.setRenderHint(QPainter::Antialiasing);
  for (int k = 0; k < 4; ++k) {
    painter.setPen(QPen(k == highlightedSide_ ? kTopSide : kOutline, 1.2));
    painter.drawLine(toLoupe(corners_[k]), toLoupe(corners_[(k + 1) % 4]));
  }
  const QPointF c = target.center();
  painter.setPen(QPen(QColor(255, 255, 255, 220), 1));
  painter.drawLine(QPointF(target.left(), c.y()), QPointF(c.x() - 6, c.y()));
  painter.drawLine(QPointF(c.x() + 6, c.y()), QPointF(target.right(), c.y()));
  painter.drawLine(QPointF(c.x(), target.top()), QPointF(c.x(), c.y() - 6));
  painter.drawLine(QPointF(c.x(), c.y() + 6), QPointF(c.x(), target.bottom()));
  painter.restore();
  painter.setPen(QPen(QColor(230, 230, 230), 2));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(target);
  QFont font = painter.font();
  font.setBold(false);
  font.setPixelSize(11);
  painter.setFont(font);
  const QString text = QStringLiteral("%1, %2 px").arg(photoPos.x(), 0, 'f', 1).arg(photoPos.y(), 0, 'f', 1);
  const QRectF caption(target.left(), target.bottom() - 18, target.width(), 18);
  painter.fillRect(caption, QColor(0, 0, 0, 160));
  painter.setPen(Qt::white);
  painter.drawText(caption, Qt::AlignCenter, text);
}

void CornerPickerView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !hasImage()) return QWidget::mousePressEvent(event);
  const QPointF photo = widgetToPhoto(event->position());
  if (patchMode_) {
    patchStart_ = clampToPhoto(photo);
    patchEnd_ = *patchStart_;
    update();
    return;
  }
  const int handle = handleAt(event->position());
  if (handle < 0) return;
  dragging_ = selected_ = handle;
  dragOffset_ = corners_[handle] - photo;
  update();
}

void CornerPickerView::mouseMoveEvent(QMouseEvent* event) {
  const QPointF photo = widgetToPhoto(event->position());
  if (patchStart_) {
    patchEnd_ = clampToPhoto(photo);
    update();
    return;
  }
  if (dragging_ >= 0) {
    corners_[dragging_] = clampToPhoto(photo + dragOffset_);
    emit cornersChanged(false);
    update();
    return;
  }
  const int hovered = handleAt(event->position());
  if (hovered != hovered_) {
    hovered_ = hovered;
    setCursor(patchMode_ ? Qt::CrossCursor : (hovered >= 0 ? Qt::SizeAllCursor : Qt::ArrowCursor));
    update();
  }
}

void CornerPickerView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return QWidget::mouseReleaseEvent(event);
  if (patchStart_) {
    const QRectF r = QRectF(*patchStart_, patchEnd_).normalized();
    patchStart_.reset();
    if (r.width() >= 1 && r.height() >= 1) {
      patch_ = r;
      emit patchPicked(r);
    }
    update();
    return;
  }
  if (dragging_ >= 0) {
    dragging_ = -1;
    emit cornersChanged(true);
    update();
  }
}

void CornerPickerView::keyPressEvent(QKeyEvent* event) {
  if (event->key() >= Qt::Key_1 && event->key() <= Qt::Key_4) {
    setSelectedCorner(event->key() - Qt::Key_1);
    return;
  }
  QPointF step;
  const qreal amount = (event->modifiers() & Qt::ShiftModifier) ? 10.0 : 1.0;
  switch (event->key()) {
    case Qt::Key_Left:
      step = {-amount, 0};
      break;
    case Qt::Key_Right:
      step = {amount, 0};
      break;
    case Qt::Key_Up:
      step = {0, -amount};
      break;
    case Qt::Key_Down:
      step = {0, amount};
      break;
    default:
      return QWidget::keyPressEvent(event);
  }
  if (!hasImage()) return;
  corners_[selected_] = clampToPhoto(corners_[selected_] + step);
  emit cornersChanged(true);
  update();
}

void CornerPickerView::leaveEvent(QEvent* event) {
  if (hovered_ >= 0 && dragging_ < 0) {
    hovered_ = -1;
    update();
  }
  QWidget::leaveEvent(event);
}

}  // namespace kerf
