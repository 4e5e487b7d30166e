#include "faces_view.hpp"

#include <QPainter>
#include <algorithm>
#include <limits>

namespace kerf {

namespace {

constexpr int kColumns = 4, kRows = 3;
constexpr qreal kMarginPx = 12;  // around the cross
constexpr qreal kGapPx = 2;      // between faces, so the edges stay visible

// Column widths and row heights of the cross in mm: the largest face in each.
struct CrossGrid {
  std::array<qreal, kColumns + 1> x{};  // cumulative, mm
  std::array<qreal, kRows + 1> y{};
};

CrossGrid crossGrid(const Block& block) {
  std::array<qreal, kColumns> width{};
  std::array<qreal, kRows> height{};
  for (FaceId face : kAllFaces) {
    const CrossSlot slot = crossSlot(face);
    const FaceFrame frame = block.face(face);
    width[slot.column] = std::max<qreal>(width[slot.column], frame.widthMm);
    height[slot.row] = std::max<qreal>(height[slot.row], frame.heightMm);
  }
  CrossGrid grid;
  for (int i = 0; i < kColumns; ++i) grid.x[i + 1] = grid.x[i] + width[i];
  for (int i = 0; i < kRows; ++i) grid.y[i + 1] = grid.y[i] + height[i];
  return grid;
}

}  // namespace

FacesView::FacesView(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent fills every pixel
  setMinimumSize(minimumSizeHint());
}

void FacesView::setFaces(const std::array<QImage, 6>& faces, const Block& block) {
  faces_ = faces;
  block_ = block;
  update();
}

void FacesView::clear() {
  faces_ = {};
  update();
}

bool FacesView::hasFaces() const {
  return std::any_of(faces_.begin(), faces_.end(), [](const QImage& image) { return !image.isNull(); });
}

void FacesView::setPlaceholderText(const QString& text) {
  placeholder_ = text;
  update();
}

void FacesView::setCaption(const QString& title, const QString& detail) {
  captionTitle_ = title;
  captionDetail_ = detail;
  update();
}

QRectF FacesView::faceRect(FaceId face) const {
  const CrossGrid grid = crossGrid(block_);
  const qreal gaps = kGapPx * (kColumns - 1), vgaps = kGapPx * (kRows - 1);
  const qreal availableW = std::max<qreal>(1, width() - 2 * kMarginPx - gaps);
  const qreal availableH = std::max<qreal>(1, height() - 2 * kMarginPx - vgaps);
  const qreal scale = std::min(availableW / grid.x[kColumns], availableH / grid.y[kRows]);  // px per mm
  const qreal crossW = grid.x[kColumns] * scale + gaps, crossH = grid.y[kRows] * scale + vgaps;
  const QPointF origin((width() - crossW) / 2, (height() - crossH) / 2);

  // A face is centred in its slot when it is smaller than the slot's largest face.
  const CrossSlot slot = crossSlot(face);
  const FaceFrame frame = block_.face(face);
  const qreal slotX = origin.x() + grid.x[slot.column] * scale + slot.column * kGapPx;
  const qreal slotY = origin.y() + grid.y[slot.row] * scale + slot.row * kGapPx;
  const qreal slotW = (grid.x[slot.column + 1] - grid.x[slot.column]) * scale;
  const qreal slotH = (grid.y[slot.row + 1] - grid.y[slot.row]) * scale;
  const qreal w = frame.widthMm * scale, h = frame.heightMm * scale;
  return {slotX + (slotW - w) / 2, slotY + (slotH - h) / 2, w, h};
}

void FacesView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(38, 38, 40));
  if (!hasFaces()) {
    painter.setPen(QColor(190, 190, 190));
    painter.drawText(rect(), Qt::AlignCenter, placeholder_);
    return;
  }
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.setRenderHint(QPainter::Antialiasing);
  // One label size for all faces, from the smallest, so the letters read as a set.
  qreal smallestSide = std::numeric_limits<qreal>::max();
  for (FaceId face : kAllFaces) {
    const QRectF r = faceRect(face);
    smallestSide = std::min({smallestSide, r.width(), r.height()});
  }
  const qreal labelSide = std::clamp(smallestSide * 0.14, 16.0, 36.0);
  for (FaceId face : kAllFaces) {
    const QRectF target = faceRect(face);
    const QImage& image = faces_[faceIndex(face)];
    if (image.isNull()) {
      painter.setPen(QPen(QColor(110, 110, 110), 1, Qt::DashLine));
      painter.setBrush(Qt::NoBrush);
      painter.drawRect(target.adjusted(0.5, 0.5, -0.5, -0.5));
    } else {
      painter.drawImage(target, image);
    }
    drawLabel(painter, target, face, labelSide);
  }
  drawCaption(painter);
}

void FacesView::drawCaption(QPainter& painter) const {
  if (captionTitle_.isEmpty()) return;
  const QRectF b = faceRect(FaceId::B), f = faceRect(FaceId::F);
  const QRectF area(QPointF(b.right() + 2 * kGapPx, b.top()), QPointF(f.right(), faceRect(FaceId::A).top()));
  const int titlePx = static_cast<int>(std::clamp(area.height() * 0.12, 14.0, 30.0));
  QFont font = painter.font();
  font.setBold(true);
  font.setPixelSize(titlePx);
  painter.setFont(font);
  painter.setPen(QColor(225, 225, 225));
  QRectF titleRect;
  painter.drawText(area, Qt::AlignRight | Qt::AlignTop, captionTitle_, &titleRect);
  font.setBold(false);
  font.setPixelSize(std::max(11, titlePx * 5 / 9));
  painter.setFont(font);
  painter.setPen(QColor(165, 165, 165));
  painter.drawText(area.adjusted(0, titleRect.height() + titlePx * 0.25, 0, 0), Qt::AlignRight | Qt::AlignTop,
                   captionDetail_);
}

void FacesView::drawLabel(QPainter& painter, const QRectF& rect, FaceId face, qreal side) const {
  // A white letter on a translucent dark badge stays readable on light and dark wood alike.
  QFont font = painter.font();
  font.setBold(true);
  font.setPixelSize(static_cast<int>(side * 0.7));
  painter.setFont(font);
  const QRectF badge(rect.left() + side * 0.25, rect.top() + side * 0.25, side, side);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(0, 0, 0, 150));
  painter.drawRoundedRect(badge, side * 0.2, side * 0.2);
  painter.setPen(Qt::white);
  painter.drawText(badge, Qt::AlignCenter, QString(QChar(faceLetter(face))));
}

}  // namespace kerf
