// CutView's photo of the real cut: Photo, Split (photo | model at a draggable line) and Difference (heat
// map and legend), drawn as the faces view draws its compare displays (compare_overlay.hpp).
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "compare_overlay.hpp"
#include "cut_view.hpp"
#include "io/cut_photo.hpp"

namespace kerf {

namespace {

constexpr double kRulerPx = 22;  // as cut_view.cpp's ruler bands

bool samePlane(const CutPlaneSetting& a, const CutPlaneSetting& b) {
  return cutPhotoBelongsTo(CutPhoto{{}, a}, b);
}

}  // namespace

void CutView::setCutPhoto(const CutPhotoPicture& picture) {
  cutPhoto_ = picture;
  update();
}

void CutView::setCutDisplay(CutDisplay display) {
  if (display == cutDisplay_) return;
  cutDisplay_ = display;
  update();
}

void CutView::setCutSplitPosition(double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (fraction == cutSplit_) return;
  cutSplit_ = fraction;
  emit cutSplitPositionChanged(fraction);
  update();
}

bool CutView::cutPhotoStale() const {
  return !cutPhoto_.photo.image.isNull() && !samePlane(cutPhoto_.plane, setting_);
}

bool CutView::showsCutPhoto() const {
  return cutDisplay_ != CutDisplay::Model && !cutPhoto_.photo.image.isNull() && !cutPhotoStale() && bounds();
}

bool CutView::differenceUpToDate() const {
  return !cutPhoto_.difference.isNull() && cutPhoto_.differencePhoto == cutPhoto_.photo.image.cacheKey() &&
         cutPhoto_.differenceModel == model_ && cutPhoto_.differenceBoard == boardWood_ &&
         cutPhoto_.differenceOfAppearance == showsCutAppearance();
}

QRectF CutView::cutRect() const {
  const auto b = bounds();
  if (!b) return {};
  return QRectF(widgetPointOf({b->min.x, b->max.y}), widgetPointOf({b->max.x, b->min.y}));
}

std::optional<qreal> CutView::cutSplitX() const {
  if (!showsCutPhoto() || cutDisplay_ != CutDisplay::Split) return std::nullopt;
  const QRectF r = cutRect();
  return std::round(r.left() + cutSplit_ * r.width());
}

void CutView::drawCutPhoto(QPainter& painter) const {
  const QRectF content = rect().adjusted(kRulerPx, 0, 0, -kRulerPx);
  if (cutDisplay_ != CutDisplay::Model && cutPhotoStale()) {
    drawCompareTag(painter, content, rect(),
                   tr("the cut photo was taken on another plane: bring the plane back to compare"),
                   Qt::AlignTop | Qt::AlignLeft);
    return;
  }
  if (!showsCutPhoto()) return;
  QPainterPath outline;
  outline.addPolygon(cutOutline());
  const QRectF area = cutRect();
  if (cutDisplay_ == CutDisplay::Photo) {
    drawSurface(painter, cutPhoto_.photo, outline);
  } else if (cutDisplay_ == CutDisplay::Split) {
    // The photo left of the line over the model's wood, already drawn; both cover the whole cut, so the
    // rings run on across the line wherever the model is right.
    const qreal x = *cutSplitX();
    QPainterPath left;
    left.addRect(
        QRectF(QPointF(std::min(x, area.left()) - 1, area.top() - 1), QPointF(x, area.bottom() + 1)));
    drawSurface(painter, cutPhoto_.photo, outline.intersected(left));
    drawSplitLine(painter, x, area.intersected(content));
    drawSplitTags(painter, area, content, x);
  } else {
    if (!cutPhoto_.difference.isNull())
      drawSurface(painter, {cutPhoto_.difference, cutPhoto_.photo.grid}, outline);
    if (!differenceUpToDate())
      drawCompareTag(painter, area, content,
                     cutPhoto_.difference.isNull() ? tr("comparing…") : tr("updating…"),
                     Qt::AlignBottom | Qt::AlignLeft);
    drawDifferenceLegend(painter, content);
  }
}

bool CutView::cutSplitPress(QMouseEvent* event) {
  const auto x = cutSplitX();
  if (event->button() != Qt::LeftButton || !x) return false;
  const QRectF r = cutRect();
  const QPointF p = event->position();
  if (std::abs(p.x() - *x) > kSplitGrabPx || p.y() < r.top() || p.y() > r.bottom()) return false;
  draggingSplit_ = true;
  event->accept();
  return true;
}

bool CutView::cutSplitMove(QMouseEvent* event) {
  if (draggingSplit_ && !(event->buttons() & Qt::LeftButton)) draggingSplit_ = false;  // released elsewhere
  if (!draggingSplit_) {
    const auto x = cutSplitX();
    const bool over = x && !panning_ && std::abs(event->position().x() - *x) <= kSplitGrabPx;
    if (over)
      setCursor(Qt::SplitHCursor);
    else if (!panning_ && cursor().shape() == Qt::SplitHCursor)
      unsetCursor();
    return false;
  }
  const QRectF r = cutRect();
  if (r.width() > 0) setCutSplitPosition((event->position().x() - r.left()) / r.width());
  event->accept();
  return true;
}

}  // namespace kerf
