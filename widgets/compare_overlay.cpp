#include "compare_overlay.hpp"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPolygonF>
#include <algorithm>
#include <cmath>

#include "face_difference.hpp"

namespace kerf {

namespace {

const QColor kTagBackground(0, 0, 0, 165);

QString tr(const char* text) {
  return QCoreApplication::translate("CompareOverlay", text);
}

}  // namespace

void drawSplitLine(QPainter& painter, qreal x, const QRectF& visible) {
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
}

void drawCompareTag(QPainter& painter, const QRectF& area, const QRectF& clip, const QString& text,
                    Qt::Alignment corner) {
  painter.save();
  QFont font = painter.font();
  font.setPixelSize(static_cast<int>(std::clamp(area.height() * 0.06, 10.0, 13.0)));
  font.setBold(false);
  painter.setFont(font);
  const QFontMetricsF metrics(font);
  const QSizeF size(metrics.horizontalAdvance(text) + 10, metrics.height() + 4);
  const qreal margin = 4;
  const qreal x = corner & Qt::AlignRight ? area.right() - margin - size.width() : area.left() + margin;
  const qreal y = corner & Qt::AlignBottom ? area.bottom() - margin - size.height() : area.top() + margin;
  const QRectF box(QPointF(x, y), size);
  painter.setClipRect(area.intersected(clip));
  painter.setPen(Qt::NoPen);
  painter.setBrush(kTagBackground);
  painter.drawRoundedRect(box, 3, 3);
  painter.setPen(QColor(235, 235, 235));
  painter.drawText(box, Qt::AlignCenter, text);
  painter.restore();
}

void drawSplitTags(QPainter& painter, const QRectF& area, const QRectF& clip, qreal x) {
  if (area.width() < 140) return;  // which side is which, where there is room
  const QRectF left(area.topLeft(), QPointF(x, area.bottom())),
      right(QPointF(x, area.top()), area.bottomRight());
  if (x - area.left() > 50)
    drawCompareTag(painter, left, clip, tr("photo"), Qt::AlignBottom | Qt::AlignRight);
  if (area.right() - x > 50)
    drawCompareTag(painter, right, clip, tr("model"), Qt::AlignBottom | Qt::AlignLeft);
}

void drawDifferenceLegend(QPainter& painter, const QRectF& area) {
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
  const QRectF box(area.right() - w - 10, area.bottom() - h - 10, w, h);
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

}  // namespace kerf
