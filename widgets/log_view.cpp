#include "log_view.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace kerf {

namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
const QColor kBackground(38, 40, 44);
const QColor kStemFill(96, 80, 58);
const QColor kStemLine(196, 170, 128);
const QColor kPith(230, 90, 60);
const QColor kAlive(110, 200, 90);
const QColor kDead(170, 95, 45);
const QColor kSelected(255, 220, 60);
const QColor kBoard(120, 190, 255);

// The eight corners of the board in the log frame, and its twelve edges as corner pairs.
std::array<glm::vec3, 8> boardCorners(const Board& board) {
  std::array<glm::vec3, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 sign((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
    corners[i] = board.toLog(0.5f * sign * board.size);
  }
  return corners;
}
constexpr std::array<std::pair<int, int>, 12> kEdges{
    {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// A knot's skeleton inside the stem: its centre line from the pith to the bark (or its last sample).
std::vector<glm::vec3> skeleton(const LogModel& log, const Knot& knot,
                                std::vector<float>* distances = nullptr) {
  std::vector<glm::vec3> points;
  const float step = std::max(knot.distanceStep, 2.0f);
  for (float d = 0.0f;; d += step) {
    const float dd = std::min(d, knot.maxDistance());
    const float z = knot.heightAt(dd), w = knot.azimuthAt(dd);
    const float r = log.stem.radiusAt(z, w);
    const float dc = std::min(dd, r);
    const glm::vec2 p = log.stem.pithAt(z) + dc * glm::vec2(std::cos(w), std::sin(w));
    points.emplace_back(p.x, p.y, z);
    if (distances) distances->push_back(dc);
    if (dd >= knot.maxDistance() || dd >= r) break;
  }
  return points;
}

double segmentDistance(QPointF p, QPointF a, QPointF b) {
  const QPointF ab = b - a;
  const double len2 = QPointF::dotProduct(ab, ab);
  const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const QPointF q = a + t * ab - p;
  return std::hypot(q.x(), q.y());
}

}  // namespace

LogView::LogView(QWidget* parent) : QWidget(parent) {
  setMouseTracking(false);
  setFocusPolicy(Qt::ClickFocus);
  setToolTip(
      tr("Drag to move the board (top view: across the log; side view: along it). Ctrl+drag in the "
         "top view turns it about the log axis. Click a knot to select it; the wheel zooms the "
         "side view."));
}

void LogView::setLog(std::shared_ptr<const LogModel> log) {
  log_ = std::move(log);
  if (log_ && selected_ >= static_cast<int>(log_->knots.size())) selected_ = -1;
  update();
}

void LogView::setBoard(const Board& board) {
  board_ = board;
  update();
}

void LogView::setSelectedKnot(int knot) {
  selected_ = knot;
  update();
}

glm::vec3 LogView::sideAcross() const {
  const glm::mat3 axes = board_.axes();
  glm::vec2 view(axes[2].x, axes[2].y);  // we look along the board's thickness, projected level
  if (glm::length(view) < 1e-3f) view = glm::vec2(axes[0].x, axes[0].y);
  if (glm::length(view) < 1e-3f) view = glm::vec2(0.0f, 1.0f);
  view = glm::normalize(view);
  return {view.y, -view.x, 0.0f};
}

LogView::Mapping LogView::topMapping() const {
  Mapping m;
  const double side = std::min<double>(height() - 24, width() * 0.34);
  m.rect = QRectF(6, 20, side, side);
  const double radius = log_ ? 1.1 * log_->stem.maxRadius() : 100.0;
  m.scale = side / (2.0 * radius);
  m.origin = m.rect.center();
  return m;
}

LogView::Mapping LogView::sideMapping() const {
  Mapping m;
  const QRectF top = topMapping().rect;
  m.rect = QRectF(top.right() + 12, 20, width() - top.right() - 18, height() - 24);
  if (!log_) return m;
  const double length = std::max(1.0f, log_->stem.height());
  const double span = sideSpanMm_ > 0 ? std::min(sideSpanMm_, length) : length;
  const double radius = 1.1 * log_->stem.maxRadius();
  m.scale = std::min(m.rect.width() / span, m.rect.height() / (2.0 * radius));
  // The window of the log shown: centred on the board, kept inside the log.
  const double shown = m.rect.width() / m.scale;
  double z0 = board_.center.z - 0.5 * shown;
  z0 = shown >= length ? -(shown - length) / 2 : std::clamp(z0, 0.0, length - shown);
  m.origin = QPointF(m.rect.left() - z0 * m.scale, m.rect.center().y());
  return m;
}

QPointF LogView::topViewPoint(const glm::vec3& p) const {
  const Mapping m = topMapping();
  return m.origin + QPointF(p.x * m.scale, -p.y * m.scale);
}

QPointF LogView::sideViewPoint(const glm::vec3& p) const {
  const Mapping m = sideMapping();
  const glm::vec3 across = sideAcross();
  return m.origin + QPointF(p.z * m.scale, -(p.x * across.x + p.y * across.y) * m.scale);
}

LogView::Panel LogView::panelAt(QPointF p) const {
  if (topMapping().rect.contains(p)) return Panel::Top;
  if (sideMapping().rect.contains(p)) return Panel::Side;
  return Panel::None;
}

void LogView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), kBackground);
  painter.setPen(palette().color(QPalette::Light));
  if (!log_) {
    painter.setPen(Qt::lightGray);
    painter.drawText(rect(), Qt::AlignCenter, tr("No log. File ▸ Open Log… or New Random Log…"));
    return;
  }
  const Mapping top = topMapping(), side = sideMapping();
  painter.setPen(Qt::lightGray);
  painter.drawText(QPointF(top.rect.left(), 14),
                   tr("Top (along the stem), z = %1 mm").arg(board_.center.z, 0, 'f', 0));
  painter.drawText(QPointF(side.rect.left(), 14), tr("Side: %1 — %2 knots, %3 m, ⌀ %4 mm")
                                                      .arg(QString::fromStdString(log_->name))
                                                      .arg(log_->knots.size())
                                                      .arg(log_->stem.height() / 1000.0, 0, 'f', 2)
                                                      .arg(2.0 * log_->stem.maxRadius(), 0, 'f', 0));
  painter.save();
  painter.setClipRect(top.rect);
  paintTop(painter, top);
  paintBoard(painter, true);
  painter.restore();
  painter.save();
  painter.setClipRect(side.rect);
  paintSide(painter, side);
  paintBoard(painter, false);
  painter.restore();
  painter.setPen(QPen(QColor(90, 90, 96), 1));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(top.rect);
  painter.drawRect(side.rect);
  // Legend, bottom right of the side view.
  const std::pair<QColor, QString> keys[] = {{kAlive, tr("alive branch")},
                                             {kDead, tr("dead branch")},
                                             {kPith, tr("pith")},
                                             {kBoard, tr("board (face A filled)")}};
  const QFontMetrics metrics = painter.fontMetrics();
  double x = side.rect.right() - 8;
  const double y = side.rect.bottom() - 8;
  for (int i = 3; i >= 0; --i) {
    const auto& [color, text] = keys[i];
    x -= metrics.horizontalAdvance(text);
    painter.setPen(Qt::lightGray);
    painter.drawText(QPointF(x, y), text);
    painter.setPen(QPen(color, 3));
    painter.drawLine(QPointF(x - 22, y - 4), QPointF(x - 6, y - 4));
    x -= 36;
  }
}

void LogView::paintTop(QPainter& painter, const Mapping&) const {
  const float z = board_.center.z;
  QPolygonF outline;
  for (int i = 0; i < 120; ++i) {
    const float w = kTwoPi * static_cast<float>(i) / 120.0f;
    const glm::vec2 p =
        log_->stem.pithAt(z) + log_->stem.radiusAt(z, w) * glm::vec2(std::cos(w), std::sin(w));
    outline << topViewPoint({p.x, p.y, z});
  }
  painter.setPen(QPen(kStemLine, 1.5));
  painter.setBrush(kStemFill);
  painter.drawPolygon(outline);
  // Knots near the board's height in full, the others faded with their distance from it.
  float zLo = 1e30f, zHi = -1e30f;
  for (const glm::vec3& c : boardCorners(board_)) {
    zLo = std::min(zLo, c.z);
    zHi = std::max(zHi, c.z);
  }
  for (int k = 0; k < static_cast<int>(log_->knots.size()); ++k) {
    const Knot& knot = log_->knots[k];
    std::vector<float> distances;
    const std::vector<glm::vec3> points = skeleton(*log_, knot, &distances);
    float kLo = 1e30f, kHi = -1e30f;
    for (const glm::vec3& p : points) {
      kLo = std::min(kLo, p.z);
      kHi = std::max(kHi, p.z);
    }
    const float gap = std::max({0.0f, zLo - kHi, kLo - zHi});
    const int alpha = static_cast<int>(255 * std::clamp(1.0f - gap / 150.0f, 0.12f, 1.0f));
    if (alpha <= 31 && k != selected_) continue;
    for (std::size_t i = 1; i < points.size(); ++i) {
      QColor c = k == selected_ ? kSelected : (knot.aliveAt(distances[i]) ? kAlive : kDead);
      c.setAlpha(k == selected_ ? 255 : alpha);
      painter.setPen(QPen(c, k == selected_ ? 3.0 : 2.0, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(topViewPoint(points[i - 1]), topViewPoint(points[i]));
    }
  }
  const glm::vec2 pith = log_->stem.pithAt(z);
  painter.setPen(Qt::NoPen);
  painter.setBrush(kPith);
  painter.drawEllipse(topViewPoint({pith.x, pith.y, z}), 3.0, 3.0);
}

void LogView::paintSide(QPainter& painter, const Mapping&) const {
  const glm::vec3 across = sideAcross();
  const float up = std::atan2(across.y, across.x);
  QPolygonF outline, pith;
  QPolygonF lower;
  for (int i = 0; i < log_->stem.slices(); ++i) {
    const float z = log_->stem.heightStep * static_cast<float>(i);
    const glm::vec2 p = log_->stem.pithAt(z);
    const glm::vec3 centre(p.x, p.y, z);
    outline << sideViewPoint(centre + log_->stem.radiusAt(z, up) * across);
    lower.prepend(sideViewPoint(centre - log_->stem.radiusAt(z, up + 0.5f * kTwoPi) * across));
    pith << sideViewPoint(centre);
  }
  outline << lower;
  painter.setPen(QPen(kStemLine, 1.5));
  painter.setBrush(kStemFill);
  painter.drawPolygon(outline);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(kPith, 1.5, Qt::DashLine));
  painter.drawPolyline(pith);
  for (int pass = 0; pass < 2; ++pass) {  // the selected knot last, on top
    for (int k = 0; k < static_cast<int>(log_->knots.size()); ++k) {
      if ((k == selected_) != (pass == 1)) continue;
      const Knot& knot = log_->knots[k];
      std::vector<float> distances;
      const std::vector<glm::vec3> points = skeleton(*log_, knot, &distances);
      for (std::size_t i = 1; i < points.size(); ++i) {
        const QColor c = k == selected_ ? kSelected : (knot.aliveAt(distances[i]) ? kAlive : kDead);
        painter.setPen(QPen(c, k == selected_ ? 3.0 : 1.6, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(sideViewPoint(points[i - 1]), sideViewPoint(points[i]));
      }
    }
  }
}

void LogView::paintBoard(QPainter& painter, bool top) const {
  const auto corners = boardCorners(board_);
  const auto at = [&](int i) { return top ? topViewPoint(corners[i]) : sideViewPoint(corners[i]); };
  painter.setPen(QPen(kBoard, 1.6));
  for (const auto& [a, b] : kEdges) painter.drawLine(at(a), at(b));
  // Face A (board +z) filled lightly, so the side it looks to is clear.
  const QPolygonF faceA{at(4), at(5), at(7), at(6)};
  QColor fill = kBoard;
  fill.setAlpha(60);
  painter.setBrush(fill);
  painter.drawPolygon(faceA);
  painter.setBrush(Qt::NoBrush);
}

int LogView::knotAt(QPointF pos) const {
  if (!log_) return -1;
  const Panel panel = panelAt(pos);
  if (panel == Panel::None) return -1;
  int best = -1;
  double bestDistance = 5.0;
  for (int k = 0; k < static_cast<int>(log_->knots.size()); ++k) {
    const std::vector<glm::vec3> points = skeleton(*log_, log_->knots[k]);
    for (std::size_t i = 1; i < points.size(); ++i) {
      const QPointF a = panel == Panel::Top ? topViewPoint(points[i - 1]) : sideViewPoint(points[i - 1]);
      const QPointF b = panel == Panel::Top ? topViewPoint(points[i]) : sideViewPoint(points[i]);
      const double d = segmentDistance(pos, a, b);
      if (d < bestDistance) {
        bestDistance = d;
        best = k;
      }
    }
  }
  return best;
}

void LogView::mousePressEvent(QMouseEvent* event) {
  if (!log_ || event->button() != Qt::LeftButton) return;
  dragPanel_ = panelAt(event->position());
  dragRotates_ = dragPanel_ == Panel::Top && (event->modifiers() & Qt::ControlModifier);
  dragMoved_ = false;
  pressPos_ = event->position();
  pressBoard_ = board_;
}

void LogView::mouseMoveEvent(QMouseEvent* event) {
  if (dragPanel_ == Panel::None) return;
  const QPointF delta = event->position() - pressPos_;
  if (!dragMoved_ && std::hypot(delta.x(), delta.y()) < 3.0) return;
  dragMoved_ = true;
  Board board = pressBoard_;
  if (dragRotates_) {
    const QPointF c = topViewPoint(pressBoard_.center);
    const QPointF a = pressPos_ - c, b = event->position() - c;
    // Angles in the log's x, y (screen y runs down).
    const double turn = std::atan2(-b.y(), b.x()) - std::atan2(-a.y(), a.x());
    // Which way ry turns the board about the log axis (counter-clockwise seen from above, or not).
    Board probe = pressBoard_;
    probe.rotationDeg.y += 1.0f;
    const glm::vec3 x0 = pressBoard_.axes()[0], x1 = probe.axes()[0];
    const float sense = x0.x * x1.y - x0.y * x1.x >= 0.0f ? 1.0f : -1.0f;
    float ry = pressBoard_.rotationDeg.y + sense * static_cast<float>(turn * 180.0 / std::numbers::pi);
    ry = std::remainder(ry, 360.0f);
    if (event->modifiers() & Qt::ShiftModifier) ry = 15.0f * std::round(ry / 15.0f);
    board.rotationDeg.y = ry;
  } else if (dragPanel_ == Panel::Top) {
    const double s = topMapping().scale;
    board.center.x += static_cast<float>(delta.x() / s);
    board.center.y += static_cast<float>(-delta.y() / s);
  } else {
    const double s = sideMapping().scale;
    const glm::vec3 across = sideAcross();
    board.center.z += static_cast<float>(delta.x() / s);
    board.center += static_cast<float>(-delta.y() / s) * across;
  }
  board_ = board;
  update();
  emit boardEdited(board_, false);
}

void LogView::mouseReleaseEvent(QMouseEvent* event) {
  if (dragPanel_ == Panel::None || event->button() != Qt::LeftButton) return;
  dragPanel_ = Panel::None;
  if (dragMoved_) {
    emit boardEdited(board_, true);
    return;
  }
  const int knot = knotAt(event->position());
  if (knot >= 0) {
    setSelectedKnot(knot);
    emit knotClicked(knot);
  }
}

void LogView::wheelEvent(QWheelEvent* event) {
  if (!log_ || panelAt(event->position()) != Panel::Side) return;
  const double length = std::max(1.0f, log_->stem.height());
  const double current = sideSpanMm_ > 0 ? std::min(sideSpanMm_, length) : length;
  const double factor = std::pow(0.8, event->angleDelta().y() / 120.0);
  sideSpanMm_ = std::clamp(current * factor, 4.0 * log_->stem.maxRadius(), length);
  update();
  event->accept();
}

}  // namespace kerf
