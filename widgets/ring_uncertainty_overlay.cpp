#include "ring_uncertainty_overlay.hpp"

#include <QObject>
#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>

namespace kerf {

namespace {

struct Step {
  float sigmaMm;
  QColor color;
};
// The colour at each step; in between, blended.
const std::array<Step, 4> kSteps = {{{0.25f, QColor(40, 170, 80)},
                                     {0.5f, QColor(230, 200, 40)},
                                     {1.0f, QColor(235, 130, 30)},
                                     {2.0f, QColor(210, 40, 40)}}};
constexpr int kOverlayAlpha = 110;

bool insideBlock(const Block& block, glm::vec3 p) {
  const glm::vec3 h = block.halfSize() + 1e-3f;
  return std::abs(p.x) <= h.x && std::abs(p.y) <= h.y && std::abs(p.z) <= h.z;
}

}  // namespace

QColor ringUncertaintyColor(float sigmaMm) {
  if (!(sigmaMm > kSteps.front().sigmaMm)) return kSteps.front().color;
  for (std::size_t i = 1; i < kSteps.size(); ++i) {
    if (sigmaMm > kSteps[i].sigmaMm) continue;
    const float t = (sigmaMm - kSteps[i - 1].sigmaMm) / (kSteps[i].sigmaMm - kSteps[i - 1].sigmaMm);
    const QColor a = kSteps[i - 1].color, b = kSteps[i].color;
    return QColor::fromRgbF(a.redF() + t * (b.redF() - a.redF()), a.greenF() + t * (b.greenF() - a.greenF()),
                            a.blueF() + t * (b.blueF() - a.blueF()));
  }
  return kSteps.back().color;
}

QString ringUncertaintyText(float sigmaMm) {
  const int digits = sigmaMm < 0.3f ? 2 : sigmaMm < 9.95f ? 1 : 0;
  return QStringLiteral("rings ±%1 mm").arg(double(sigmaMm), 0, 'f', digits);
}

QImage ringUncertaintyImage(const RingUncertainty& uncertainty, const Block& block, const CutPlane& plane,
                            const PlaneRect& rect, float stepMm) {
  const int w = std::clamp(static_cast<int>(std::ceil((rect.max.x - rect.min.x) / stepMm)), 1, 1024);
  const int h = std::clamp(static_cast<int>(std::ceil((rect.max.y - rect.min.y) / stepMm)), 1, 1024);
  QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec2 q(rect.min.x + (x + 0.5f) * (rect.max.x - rect.min.x) / w,
                        rect.max.y - (y + 0.5f) * (rect.max.y - rect.min.y) / h);
      const glm::vec3 p = plane.toBlock(q);
      if (!insideBlock(block, p)) continue;
      QColor c = ringUncertaintyColor(uncertainty.at(block, p));
      c.setAlpha(kOverlayAlpha);
      image.setPixelColor(x, y, c);
    }
  return image;
}

void drawRingUncertaintyLegend(QPainter& painter, const QRectF& area) {
  const QString title = QObject::tr("How sure the rings are (1σ)");
  QFont font = painter.font();
  font.setPixelSize(11);
  painter.setFont(font);
  const QFontMetricsF metrics(font);
  const double rowH = metrics.height() + 2, swatch = 12;
  const double width =
      std::max(metrics.horizontalAdvance(title), metrics.horizontalAdvance("rings ±2 mm or more")) + swatch +
      20;
  const QRectF box(area.right() - width - 8, area.top() + 8, width, rowH * (kSteps.size() + 1) + 8);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(20, 18, 16, 190));
  painter.drawRoundedRect(box, 4, 4);
  painter.setPen(QColor(235, 230, 220));
  painter.drawText(QRectF(box.left() + 6, box.top() + 4, box.width() - 12, rowH), Qt::AlignLeft, title);
  for (std::size_t i = 0; i < kSteps.size(); ++i) {
    const double top = box.top() + 4 + rowH * double(i + 1);
    painter.fillRect(QRectF(box.left() + 6, top + (rowH - swatch) / 2, swatch, swatch), kSteps[i].color);
    const QString label =
        i + 1 == kSteps.size() ? QObject::tr("rings ±2 mm or more") : ringUncertaintyText(kSteps[i].sigmaMm);
    painter.drawText(QRectF(box.left() + 12 + swatch, top, box.width() - swatch - 18, rowH), Qt::AlignLeft,
                     label);
  }
}

}  // namespace kerf
