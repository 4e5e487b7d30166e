#include "faces_view.hpp"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QUrl>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>

#include "compare_overlay.hpp"
#include "face_difference_maps.hpp"

namespace kerf {

namespace {

// Millimetres with `decimals` decimals, never "-0.00".
QString mm(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  return QString::number(rounded == 0 ? 0.0 : rounded, 'f', decimals);
}

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

bool anyImage(const std::array<QImage, 6>& images) {
  return std::any_of(images.begin(), images.end(), [](const QImage& image) { return !image.isNull(); });
}

enum class DropKind { None, Image, Document };

DropKind dropKind(const QString& path) {
  const QFileInfo info(path);
  if (path.isEmpty()) return DropKind::None;
  if (info.isDir()) return DropKind::Document;
  const QString suffix = info.suffix().toLower();
  if (suffix == QLatin1String("kerf")) return DropKind::Document;
  static const QStringList images{"png", "jpg", "jpeg", "tif", "tiff"};
  return images.contains(suffix) ? DropKind::Image : DropKind::None;
}

QStringList localPaths(const QMimeData* mime) {
  QStringList paths;
  if (!mime || !mime->hasUrls()) return paths;
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile()) paths << url.toLocalFile();
  return paths;
}

// "A_col.png", "b.jpg", "C-photo.tif" -> that face; anything else -> nothing.
std::optional<FaceId> faceFromFileName(const QString& path) {
  const QString name = QFileInfo(path).completeBaseName();
  if (name.isEmpty()) return std::nullopt;
  if (name.size() > 1 && name[1].isLetterOrNumber()) return std::nullopt;
  return faceFromLetter(name[0].toLatin1());
}

}  // namespace

FacesView::FacesView(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent fills every pixel
  setMinimumSize(minimumSizeHint());
  setMouseTracking(true);
  setAcceptDrops(true);
  setFocusPolicy(Qt::StrongFocus);
  differences_ = new FaceDifferenceMaps(this);
  connect(differences_, &FaceDifferenceMaps::ready, this, [this] {
    update();
    emit differenceReady();
  });
}

// --- Content ----------------------------------------------------------------------------------------

void FacesView::setBlock(const Block& block) {
  if (block.size() != block_.size()) {
    zoom_ = 1.0;  // another block: start from the whole cross
    pan_ = {};
  }
  block_ = block;
  update();
}

void FacesView::setPhotos(const std::array<QImage, 6>& photos) {
  photos_ = photos;
  differencesStale_ = true;
  requestDifferences();
  update();
}

void FacesView::setRenderings(const std::array<QImage, 6>& renderings) {
  renderings_ = renderings;
  differencesStale_ = true;
  requestDifferences();
  update();
}

void FacesView::setFaces(const std::array<QImage, 6>& faces, const Block& block) {
  setBlock(block);
  photos_ = faces;
  renderings_ = {};
  differencesStale_ = true;
  requestDifferences();
  update();
}

void FacesView::clear() {
  photos_ = {};
  renderings_ = {};
  differencesStale_ = true;
  requestDifferences();
  update();
}

void FacesView::setOverlayPolylines(const std::array<std::vector<QPolygonF>, 6>& polylines,
                                    const std::array<QSize, 6>& imageSizes,
                                    const std::array<std::vector<QColor>, 6>& colors) {
  overlay_ = polylines;
  overlaySizes_ = imageSizes;
  overlayColors_ = colors;
  update();
}

void FacesView::clearOverlay() {
  overlay_ = {};
  overlaySizes_ = {};
  overlayColors_ = {};
  update();
}

bool FacesView::hasOverlay() const {
  return std::any_of(overlay_.begin(), overlay_.end(), [](const auto& lines) { return !lines.empty(); });
}

void FacesView::setOverlayVisible(bool visible) {
  if (visible == overlayVisible_) return;
  overlayVisible_ = visible;
  update();
}

void FacesView::drawOverlay(QPainter& painter, const QRectF& target, FaceId face) const {
  const int i = faceIndex(face);
  const QSize size = overlaySizes_[i];
  if (!overlayVisible_ || overlay_[i].empty() || size.isEmpty()) return;
  painter.save();
  painter.setClipRect(target.intersected(rect()));
  painter.translate(target.topLeft());
  painter.scale(target.width() / size.width(), target.height() / size.height());
  // Cosmetic pens keep their width whatever the zoom; a dark outline keeps the colour readable on
  // light and dark wood alike.
  QPen outline(QColor(0, 0, 0, 150), 3.0);
  outline.setCosmetic(true);
  QPen line(QColor(255, 40, 200), 1.6);
  line.setCosmetic(true);
  const std::vector<QColor>& colors = overlayColors_[i];
  for (const bool outlinePass : {true, false}) {
    for (std::size_t k = 0; k < overlay_[i].size(); ++k) {
      QPen pen = outlinePass ? outline : line;
      if (!outlinePass && k < colors.size()) pen.setColor(colors[k]);
      painter.setPen(pen);
      painter.drawPolyline(overlay_[i][k]);
    }
  }
  painter.restore();
}

FacesView::Layers FacesView::layers() const {
  const bool photos = anyImage(photos_), model = anyImage(renderings_);
  if (!photos) return {&renderings_, nullptr};
  if (!model) return {&photos_, nullptr};
  switch (display_) {
    case FaceDisplay::Photos:
      return {&photos_, nullptr};
    case FaceDisplay::Model:
      return {&renderings_, nullptr};
    case FaceDisplay::Blend:
      return {&photos_, &renderings_};
    case FaceDisplay::Split:
    case FaceDisplay::Difference:
      return {&photos_, nullptr};  // drawn by drawCompareFace; the photos name the pixels
  }
  return {&photos_, nullptr};
}

bool FacesView::comparing() const {
  return (display_ == FaceDisplay::Split || display_ == FaceDisplay::Difference) && anyImage(photos_) &&
         anyImage(renderings_);
}

const std::array<QImage, 6>& FacesView::faces() const {
  return *layers().base;
}

bool FacesView::hasFaces() const {
  return anyImage(photos_) || anyImage(renderings_);
}

void FacesView::setDisplay(FaceDisplay display) {
  if (display == display_) return;
  display_ = display;
  requestDifferences();
  emit displayChanged(display);
  update();
}

void FacesView::setBlendOpacity(double opacity) {
  blendOpacity_ = std::clamp(opacity, 0.0, 1.0);
  update();
}

void FacesView::setForegroundPainter(std::function<void(QPainter&)> painter) {
  foreground_ = std::move(painter);
  update();
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

// --- Layout and navigation --------------------------------------------------------------------------

QRectF FacesView::fitRect(FaceId face) const {
  return faceRect(face, 1.0, QPointF());
}

QRectF FacesView::faceRect(FaceId face) const {
  return faceRect(face, zoom_, pan_);
}

QPointF FacesView::gapOffset(FaceId face) {
  const CrossSlot slot = crossSlot(face);
  return {slot.column * kGapPx, slot.row * kGapPx};
}

QRectF FacesView::faceRect(FaceId face, double zoom, QPointF pan) const {
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
  const qreal slotW = (grid.x[slot.column + 1] - grid.x[slot.column]) * scale;
  const qreal slotH = (grid.y[slot.row + 1] - grid.y[slot.row]) * scale;
  const qreal w = frame.widthMm * scale, h = frame.heightMm * scale;
  const QPointF topLeft(origin.x() + grid.x[slot.column] * scale + (slotW - w) / 2,
                        origin.y() + grid.y[slot.row] * scale + (slotH - h) / 2);
  // Zoom and pan scale the wood about the view's centre; the gaps between faces stay a few pixels.
  const QPointF centre(width() / 2.0, height() / 2.0);
  return {(topLeft - centre) * zoom + centre + pan + gapOffset(face), QSizeF(w, h) * zoom};
}

const std::array<double, 16>& FacesView::zoomLadder() {
  static const std::array<double, 16> ladder{0.5, 0.67, 0.75, 1.0,  1.25, 1.5,  2.0,  3.0,
                                             4.0, 6.0,  8.0,  12.0, 16.0, 24.0, 32.0, 48.0};
  return ladder;
}

void FacesView::setZoom(double zoom, std::optional<QPointF> anchor) {
  const auto& ladder = zoomLadder();
  zoom = std::clamp(zoom, ladder.front(), ladder.back());
  const QPointF centre(width() / 2.0, height() / 2.0);
  const QPointF a = anchor.value_or(centre);
  // The point under the anchor stays there: screen = (p - centre) * zoom + centre + pan + gap offset.
  const auto face = faceAt(a);
  const QPointF gap = face ? gapOffset(*face) : QPointF();
  pan_ = a - centre - gap - (a - centre - pan_ - gap) * (zoom / zoom_);
  zoom_ = zoom;
  if (zoom_ == 1.0 && std::abs(pan_.x()) < 0.5 && std::abs(pan_.y()) < 0.5) pan_ = {};
  emit zoomChanged(zoom_);
  updateCursorText(mapFromGlobal(QCursor::pos()));
  update();
}

void FacesView::zoomIn(std::optional<QPointF> anchor) {
  for (double step : zoomLadder())
    if (step > zoom_ * 1.001) return setZoom(step, anchor);
}

void FacesView::zoomOut(std::optional<QPointF> anchor) {
  const auto& ladder = zoomLadder();
  for (auto it = ladder.rbegin(); it != ladder.rend(); ++it)
    if (*it < zoom_ / 1.001) return setZoom(*it, anchor);
}

void FacesView::fitToView() {
  zoom_ = 1.0;
  pan_ = {};
  emit zoomChanged(zoom_);
  update();
}

void FacesView::panBy(QPointF delta) {
  pan_ += delta;
  update();
}

// --- Cursor -----------------------------------------------------------------------------------------

std::optional<FaceId> FacesView::faceAt(QPointF pos) const {
  if (!hasFaces()) return std::nullopt;
  for (FaceId face : kAllFaces)
    if (faceRect(face).contains(pos)) return face;
  return std::nullopt;
}

std::optional<glm::vec3> FacesView::blockPointAt(QPointF pos) const {
  const auto face = faceAt(pos);
  if (!face) return std::nullopt;
  const QRectF r = faceRect(*face);
  // Continuous image coordinates of a nominal image: the block point does not depend on the resolution.
  const glm::ivec2 size(1000, 1000);
  const glm::vec2 image((pos.x() - r.left()) / r.width() * size.x, (pos.y() - r.top()) / r.height() * size.y);
  return block_.imageToBlock(*face, image, size);
}

QString FacesView::positionText(QPointF pos) const {
  const auto face = faceAt(pos);
  if (!face) return {};
  const QRectF r = faceRect(*face);
  const Layers shown = layers();
  const QImage& image = !(*shown.base)[faceIndex(*face)].isNull() ? (*shown.base)[faceIndex(*face)]
                        : shown.overlay                           ? (*shown.overlay)[faceIndex(*face)]
                                                                  : QImage();
  const glm::vec3 p = *blockPointAt(pos);
  QString pixel;
  if (!image.isNull()) {
    const int column =
        std::clamp(static_cast<int>((pos.x() - r.left()) / r.width() * image.width()), 0, image.width() - 1);
    const int row = std::clamp(static_cast<int>((pos.y() - r.top()) / r.height() * image.height()), 0,
                               image.height() - 1);
    pixel = tr(" · pixel %1, %2").arg(column).arg(row);
  }
  return tr("Face %1%2 · block x %3, y %4, z %5 mm")
      .arg(QChar(faceLetter(*face)), pixel, mm(p.x, 2), mm(p.y, 2), mm(p.z, 2));
}

void FacesView::updateCursorText(std::optional<QPointF> pos) {
  const QString text = pos && rect().contains(pos->toPoint()) ? positionText(*pos) : QString();
  if (text == lastCursorText_) return;
  lastCursorText_ = text;
  emit cursorPositionChanged(text);
}

// --- Input ------------------------------------------------------------------------------------------

void FacesView::wheelEvent(QWheelEvent* event) {
  // Touchpads send fractions of a notch: one ladder step per 120 units.
  wheelAccumulator_ += event->angleDelta().y();
  while (wheelAccumulator_ >= 120) {
    wheelAccumulator_ -= 120;
    zoomIn(event->position());
  }
  while (wheelAccumulator_ <= -120) {
    wheelAccumulator_ += 120;
    zoomOut(event->position());
  }
  event->accept();
}

void FacesView::mousePressEvent(QMouseEvent* event) {
  if (splitMousePress(event)) return;
  if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && spaceHeld_)) {
    panning_ = true;
    lastMouse_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  QWidget::mousePressEvent(event);
}

void FacesView::mouseMoveEvent(QMouseEvent* event) {
  if (splitMouseMove(event)) return updateCursorText(event->position());
  if (panning_) {
    panBy(event->position() - lastMouse_);
    lastMouse_ = event->position();
  }
  updateCursorText(event->position());
}

void FacesView::mouseReleaseEvent(QMouseEvent* event) {
  if (splitMouseRelease(event)) return;
  if (panning_ && (event->button() == Qt::MiddleButton || event->button() == Qt::LeftButton)) {
    panning_ = false;
    if (spaceHeld_)
      setCursor(Qt::OpenHandCursor);
    else
      unsetCursor();
    event->accept();
    return;
  }
  QWidget::mouseReleaseEvent(event);
}

void FacesView::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) fitToView();
}

void FacesView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Space:
      if (!event->isAutoRepeat()) {
        spaceHeld_ = true;
        if (!panning_) setCursor(Qt::OpenHandCursor);
      }
      break;
    case Qt::Key_F:
      fitToView();
      break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
      zoomIn();
      break;
    case Qt::Key_Minus:
      zoomOut();
      break;
    default:
      QWidget::keyPressEvent(event);
      return;
  }
  event->accept();
}

void FacesView::keyReleaseEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
    spaceHeld_ = false;
    if (!panning_) unsetCursor();
    event->accept();
    return;
  }
  QWidget::keyReleaseEvent(event);
}

void FacesView::focusOutEvent(QFocusEvent* event) {
  spaceHeld_ = false;  // the release may go elsewhere
  if (!panning_) unsetCursor();
  QWidget::focusOutEvent(event);
}

void FacesView::leaveEvent(QEvent*) {
  updateCursorText(std::nullopt);
}

bool FacesView::acceptDrag(QDropEvent* event) {
  const QStringList paths = localPaths(event->mimeData());
  bool document = false, named = false;
  int images = 0;
  for (const QString& path : paths) {
    const DropKind kind = dropKind(path);
    document |= kind == DropKind::Document;
    if (kind == DropKind::Image) {
      ++images;
      named |= faceFromFileName(path).has_value();
    }
  }
  dropFace_.reset();
  if (!document && images == 1) dropFace_ = faceAt(event->position());
  const bool useful = document || (images == 1 && dropFace_) || (images > 1 && named);
  update();
  return useful;
}

void FacesView::dragEnterEvent(QDragEnterEvent* event) {
  // Accept any file we could use, so that dragMoveEvent follows the cursor over the faces.
  const QStringList paths = localPaths(event->mimeData());
  const bool any =
      std::any_of(paths.begin(), paths.end(), [](const QString& p) { return dropKind(p) != DropKind::None; });
  if (!any) return event->ignore();
  acceptDrag(event);
  event->acceptProposedAction();
}

void FacesView::dragMoveEvent(QDragMoveEvent* event) {
  if (acceptDrag(event))
    event->acceptProposedAction();
  else
    event->ignore();
}

void FacesView::dragLeaveEvent(QDragLeaveEvent*) {
  dropFace_.reset();
  update();
}

void FacesView::dropEvent(QDropEvent* event) {
  const bool useful = acceptDrag(event);
  const std::optional<FaceId> target = dropFace_;
  dropFace_.reset();
  update();
  if (!useful) return event->ignore();
  const QStringList paths = localPaths(event->mimeData());
  event->acceptProposedAction();
  for (const QString& path : paths)
    if (dropKind(path) == DropKind::Document) {
      emit documentDropped(path);  // a document replaces everything: the rest is ignored
      return;
    }
  QStringList images;
  for (const QString& path : paths)
    if (dropKind(path) == DropKind::Image) images << path;
  if (images.size() == 1) {
    if (target) emit photoDropped(*target, images.front());
    return;
  }
  for (const QString& path : images)
    if (const auto face = faceFromFileName(path)) emit photoDropped(*face, path);
}

// --- Drawing ----------------------------------------------------------------------------------------

void FacesView::drawFace(QPainter& painter, const QRectF& target, const QImage& image) const {
  // Magnified photos show their pixels (a woodworker checks the real grain, not interpolation);
  // reduced ones are filtered.
  const bool magnified = target.width() > 4.0 * image.width();
  painter.setRenderHint(QPainter::SmoothPixmapTransform, !magnified);
  const QRectF visible = target.intersected(rect());
  if (visible.isEmpty()) return;
  if (visible == target) {
    painter.drawImage(target, image);
    return;
  }
  // Zoomed in: only the part on screen.
  const double sx = image.width() / target.width(), sy = image.height() / target.height();
  const QRectF source((visible.left() - target.left()) * sx, (visible.top() - target.top()) * sy,
                      visible.width() * sx, visible.height() * sy);
  painter.drawImage(visible, image, source);
}

void FacesView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(38, 38, 40));
  if (!hasFaces()) {
    painter.setPen(QColor(190, 190, 190));
    painter.drawText(rect(), Qt::AlignCenter, placeholder_);
    return;
  }
  painter.setRenderHint(QPainter::Antialiasing);
  // One label size for all faces, from the smallest at fit, so the letters read as a set.
  qreal smallestSide = std::numeric_limits<qreal>::max();
  for (FaceId face : kAllFaces) {
    const QRectF r = fitRect(face);
    smallestSide = std::min({smallestSide, r.width(), r.height()});
  }
  const qreal labelSide = std::clamp(smallestSide * 0.14, 16.0, 36.0);
  const Layers shown = layers();
  const bool compare = comparing();
  for (FaceId face : kAllFaces) {
    const QRectF target = faceRect(face);
    const QImage& base = (*shown.base)[faceIndex(face)];
    const QImage overlay = shown.overlay ? (*shown.overlay)[faceIndex(face)] : QImage();
    if (compare) {
      drawCompareFace(painter, target, face);
    } else if (base.isNull() && overlay.isNull()) {
      painter.setPen(QPen(QColor(110, 110, 110), 1, Qt::DashLine));
      painter.setBrush(Qt::NoBrush);
      painter.drawRect(target.adjusted(0.5, 0.5, -0.5, -0.5));
    } else {
      if (!base.isNull()) drawFace(painter, target, base);
      if (!overlay.isNull()) {
        painter.setOpacity(base.isNull() ? 1.0 : blendOpacity_);
        drawFace(painter, target, overlay);
        painter.setOpacity(1.0);
      }
    }
    if (dropFace_ == face) {
      painter.setPen(QPen(QColor(90, 170, 255), 3));
      painter.setBrush(QColor(90, 170, 255, 50));
      painter.drawRect(target.adjusted(1.5, 1.5, -1.5, -1.5));
    }
  }
  if (foreground_) {
    painter.save();
    foreground_(painter);
    painter.restore();
  }
  // Over the annotations: a fit's residual colours sit on the very traces they grade.
  for (FaceId face : kAllFaces) drawOverlay(painter, faceRect(face), face);
  for (FaceId face : kAllFaces) drawLabel(painter, faceRect(face), face, labelSide);  // letters on top
  drawCaption(painter);
  if (compare && display_ == FaceDisplay::Difference) drawDifferenceLegend(painter, rect());
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
