#include "cut_view.hpp"

#include <QAction>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QScreen>
#include <QVector3D>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "gpu/board_wood_textures.hpp"
#include "gpu/gl_helpers.hpp"
#include "gpu/wood_program.hpp"
#include "ring_uncertainty_overlay.hpp"

namespace kerf {

namespace {

// Millimetres with `decimals` decimals, never "-0.00".
QString mm(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  return QString::number(rounded == 0 ? 0.0 : rounded, 'f', decimals);
}

constexpr double kRulerPx = 22;      // thickness of the ruler bands
constexpr double kFitMarginPx = 16;  // around the cut when fitting
constexpr double kZoomStep = 1.25;   // one wheel notch or key press

// The plane's intersection with the block as a convex polygon in plane coordinates, counter-clockwise.
std::vector<glm::vec2> cutPolygon(const CutPlane& plane, const Block& block) {
  std::vector<glm::vec2> points;
  for (const glm::vec3& p : plane.polygonInBlock(block)) points.push_back(plane.toPlane(p));
  return points;
}

// The smallest step of 1, 2, 5 x 10^k mm that is at least `minimumMm`.
double niceStep(double minimumMm) {
  const double decade = std::pow(10.0, std::floor(std::log10(minimumMm)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= minimumMm * (1 - 1e-9)) return m * decade;
  return 10 * decade;
}

QString formatMm(double value, double step) {
  const int decimals = step >= 1 ? 0 : (step >= 0.1 ? 1 : 2);
  if (std::abs(value) < step * 1e-6) value = 0;  // no "-0"
  return QString::number(value, 'f', decimals);
}

}  // namespace

CutView::CutView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  setFormat(format);
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(minimumSizeHint());
  pixelsPerMm_ = screenPixelsPerMm();

  setClock(nullptr);
  refineTimer_.setSingleShot(true);
  refineTimer_.setInterval(kRefineDelayMs);
  connect(&refineTimer_, &QTimer::timeout, this, [this] {
    interactive_ = false;
    if (lastScale_ != 1) update();
  });

  auto makeAction = [this](const QString& text, QList<QKeySequence> keys, auto slot) {
    auto* action = new QAction(text, this);
    action->setShortcuts(keys);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(action, &QAction::triggered, this, slot);
    addAction(action);
    return action;
  };
  actualSizeAction_ =
      makeAction(tr("Actual Size (1:1)"), {QKeySequence(Qt::Key_1)}, [this] { zoomToActualSize(); });
  fitAction_ = makeAction(tr("Fit Cut"), {QKeySequence(Qt::Key_F)}, [this] { zoomToFit(); });
  zoomInAction_ = makeAction(tr("Zoom In"), {QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Equal)},
                             [this] { zoomBy(kZoomStep, rect().center()); });
  zoomOutAction_ = makeAction(tr("Zoom Out"), {QKeySequence(Qt::Key_Minus)},
                              [this] { zoomBy(1 / kZoomStep, rect().center()); });
  showRingUncertaintyAction_ =
      makeAction(tr("Show How Sure the Rings Are"), {QKeySequence(Qt::Key_U)}, [this] { update(); });
  showRingUncertaintyAction_->setCheckable(true);
  showRingUncertaintyAction_->setChecked(false);  // the wood first; the status bar says the numbers
  showRingUncertaintyAction_->setToolTip(
      tr("Tint the cut by how far the fitted rings may be from the real ones (1 sigma): green within "
         "±0.25 mm, red ±2 mm or more. Known after a fit (Rings ▸ Fit Growth Field or Reconstruct)."));
  setContextMenuPolicy(Qt::ActionsContextMenu);
}

void CutView::setRingUncertainty(std::shared_ptr<const RingUncertainty> uncertainty) {
  ringUncertainty_ = std::move(uncertainty);
  update();
}

bool CutView::showsRingUncertainty() const {
  return ringUncertainty_ && !ringUncertainty_->empty() && showRingUncertaintyAction_->isChecked() &&
         model_ && !boardWood_ && bounds();
}

CutView::~CutView() {
  // ~QOpenGLWidget destroys the context after this destructor: its aboutToBeDestroyed must not call
  // cleanupGL on what is by then no longer a CutView (UBSan: vptr).
  if (context()) disconnect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &CutView::cleanupGL);
  cleanupGL();
}

void CutView::cleanupGL() {
  if (!program_ && !vertexArray_) return;  // never initialised, or already cleaned up
  makeCurrent();
  program_.reset();
  boardProgram_.reset();
  boardTextures_.reset();
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
  if (vertexBuffer_) glDeleteBuffers(1, &vertexBuffer_);
  if (smallFbo_) glDeleteFramebuffers(1, &smallFbo_);
  if (smallColor_) glDeleteTextures(1, &smallColor_);
  vertexArray_ = vertexBuffer_ = smallFbo_ = smallColor_ = growthTexture_ = 0;
  smallSize_ = {};
  uploadedModel_.reset();
  doneCurrent();
}

QColor CutView::rulerColor() {
  return {228, 219, 196};  // boxwood
}

QColor CutView::backgroundColor() {
  return {38, 38, 40};
}

// --- State ------------------------------------------------------------------------------------------

void CutView::setModel(std::shared_ptr<const WoodModel> model) {
  const bool sameBlock = model_ && model && model_->block().size() == model->block().size();
  model_ = std::move(model);
  if (!sameBlock) cutChanged();
  changedInteractively();
  update();
}

void CutView::setBoardWood(std::shared_ptr<const BoardWood> wood) {
  if (wood == boardWood_) return;
  boardWood_ = std::move(wood);
  changedInteractively();
  update();
  emit boardWoodChanged();
}

void CutView::setCutPlane(const CutPlaneSetting& setting) {
  setting_ = setting;
  cutChanged();
  changedInteractively();
  update();
}

void CutView::setCutAppearance(const CutAppearance& cut) {
  appearance_ = cut;
  update();
}

bool CutView::showsCutAppearance() const {
  return model_ && appearance_.model == model_ && !boardWood_ && appearance_.plane == setting_ &&
         !appearance_.surface.image.isNull() && bounds();
}

void CutView::drawCutAppearance(QPainter& painter) const {
  QPainterPath clip;
  clip.addPolygon(cutOutline());
  drawSurface(painter, appearance_.surface, clip);
}

// A picture mapped onto the cut: its pixel (x, y) centre lies at grid.point(x, y) in the block, which the
// plane's frame and the zoom put on the widget (an affine map, so one QTransform).
void CutView::drawSurface(QPainter& painter, const SurfaceImage& surface, const QPainterPath& clip) const {
  const SurfaceGrid& grid = surface.grid;
  const auto widgetOf = [&](float x, float y) {
    return widgetPointOf(plane_->toPlane(grid.point(x - 0.5f, y - 0.5f)));  // image coordinates: pixel edges
  };
  const QPointF o = widgetOf(0, 0), ex = widgetOf(1, 0) - o, ey = widgetOf(0, 1) - o;
  painter.save();
  painter.setClipPath(clip);
  painter.setTransform(QTransform(ex.x(), ex.y(), ey.x(), ey.y(), o.x(), o.y()));
  painter.setRenderHint(QPainter::SmoothPixmapTransform);  // bilinear, as the 3D view's textures
  painter.drawImage(QPointF(0, 0), surface.image);
  painter.restore();
}

std::optional<CutPlane> CutView::plane() const {
  if (!model_ || !plane_ || !plane_->boundsInBlock(model_->block())) return std::nullopt;
  return plane_;
}

std::optional<PlaneRect> CutView::bounds() const {
  if (!model_ || !plane_) return std::nullopt;
  return plane_->boundsInBlock(model_->block());
}

void CutView::cutChanged() {
  try {
    plane_ = setting_.plane();
  } catch (const std::exception&) {
    plane_.reset();
  }
  reframe();
  if (cursorInside_) updateCursorText(cursor_);
}

void CutView::reframe() {
  const auto b = bounds();
  if (!b || framing_ == Framing::Free) return;
  const double contentW = std::max(1.0, width() - kRulerPx), contentH = std::max(1.0, height() - kRulerPx);
  if (framing_ == Framing::Fit) {
    const glm::vec2 extent = b->max - b->min;
    const double ppm =
        std::min((contentW - 2 * kFitMarginPx) / extent.x, (contentH - 2 * kFitMarginPx) / extent.y);
    pixelsPerMm_ = std::clamp(ppm, kMinPixelsPerMm, kMaxPixelsPerMm);
  } else {
    pixelsPerMm_ = std::clamp(screenPixelsPerMm(), kMinPixelsPerMm, kMaxPixelsPerMm);
  }
  // The cut's centre at the centre of the area the rulers leave free.
  const glm::vec2 cutCentre = (b->min + b->max) * 0.5f;
  const QPointF contentCentre(kRulerPx + contentW / 2, contentH / 2);
  center_ = cutCentre - glm::vec2((contentCentre.x() - width() / 2.0) / pixelsPerMm_,
                                  -(contentCentre.y() - height() / 2.0) / pixelsPerMm_);
  emit zoomChanged(pixelsPerMm_);
}

double CutView::screenPixelsPerMm() const {
  if (screenPixelsPerMmOverride_ > 0) return screenPixelsPerMmOverride_;
  // physicalDotsPerInch: device-independent pixels per inch of the monitor's reported size.
  double dpi = 0;
  if (const QScreen* s = screen()) dpi = s->physicalDotsPerInch();
  if (!(dpi >= 50 && dpi <= 600)) dpi = logicalDpiX();
  if (!(dpi >= 50 && dpi <= 600)) dpi = 96;
  return dpi / 25.4;
}

void CutView::setScreenPixelsPerMm(double pixelsPerMm) {
  screenPixelsPerMmOverride_ = pixelsPerMm > 0 ? pixelsPerMm : 0;
  if (framing_ == Framing::ActualSize) reframe();
  update();
}

void CutView::setPixelsPerMm(double pixelsPerMm, QPointF anchor) {
  const double ppm = std::clamp(pixelsPerMm, kMinPixelsPerMm, kMaxPixelsPerMm);
  const glm::vec2 q = planePointAt(anchor);
  pixelsPerMm_ = ppm;
  center_ = glm::vec2(q.x - (anchor.x() - width() / 2.0) / ppm, q.y + (anchor.y() - height() / 2.0) / ppm);
  framing_ = Framing::Free;
  if (cursorInside_) updateCursorText(cursor_);
  emit zoomChanged(pixelsPerMm_);
  update();
}

void CutView::setZoom(double pixelsPerMm) {
  setPixelsPerMm(pixelsPerMm, QPointF(width() / 2.0, height() / 2.0));
}

void CutView::zoomBy(double factor, QPointF anchor) {
  setPixelsPerMm(pixelsPerMm_ * factor, anchor);
}

void CutView::zoomToFit() {
  framing_ = Framing::Fit;
  reframe();
  update();
}

void CutView::zoomToActualSize() {
  framing_ = Framing::ActualSize;
  reframe();
  update();
}

void CutView::setAdaptiveResolution(bool on) {
  adaptive_ = on;
  update();
}

void CutView::setForcedRenderScale(int scale) {
  forcedScale_ = std::clamp(scale, 0, 16);
  update();
}

void CutView::setClock(Clock clock) {
  if (!clock)
    clock = [timer = std::make_shared<QElapsedTimer>()] {
      if (!timer->isValid()) timer->start();
      return timer->elapsed();
    };
  clock_ = std::move(clock);
  // A new clock starts without a stream of changes.
  lastChangeMs_.reset();
  interactive_ = false;
  refineTimer_.stop();
}

void CutView::setInteractiveFrameBudgetMs(double ms) {
  budgetMs_ = std::max(1.0, ms);
}

// --- Geometry ---------------------------------------------------------------------------------------

glm::vec2 CutView::planePointAt(QPointF p) const {
  return {static_cast<float>(center_.x + (p.x() - width() / 2.0) / pixelsPerMm_),
          static_cast<float>(center_.y - (p.y() - height() / 2.0) / pixelsPerMm_)};
}

QPointF CutView::widgetPointOf(glm::vec2 q) const {
  return {width() / 2.0 + (q.x - center_.x) * pixelsPerMm_,
          height() / 2.0 - (q.y - center_.y) * pixelsPerMm_};
}

std::optional<glm::vec3> CutView::blockPointAt(QPointF widgetPos) const {
  if (!bounds()) return std::nullopt;
  const glm::vec3 p = plane_->toBlock(planePointAt(widgetPos));
  if (!model_->block().contains(p, 1e-3f)) return std::nullopt;
  return p;
}

QString CutView::positionText(QPointF widgetPos) const {
  const auto p = blockPointAt(widgetPos);
  if (!p) return {};
  const glm::vec2 ruler = planePointAt(widgetPos) - bounds()->min;
  const QString where = tr("Cut %1, %2 mm · Block x %3, y %4, z %5 mm")
                            .arg(mm(ruler.x, 1), mm(ruler.y, 1), mm(p->x, 2), mm(p->y, 2), mm(p->z, 2));
  if (!ringUncertainty_ || ringUncertainty_->empty() || boardWood_) return where;
  return where + QStringLiteral(" · ") + ringUncertaintyText(ringUncertainty_->at(model_->block(), *p));
}

QPolygonF CutView::cutOutline() const {
  QPolygonF polygon;
  if (!bounds()) return polygon;
  for (glm::vec2 q : cutPolygon(*plane_, model_->block())) polygon << widgetPointOf(q);
  return polygon;
}

QRectF CutView::bottomRulerRect() const {
  return {0, height() - kRulerPx, static_cast<qreal>(width()), kRulerPx};
}

QRectF CutView::leftRulerRect() const {
  return {0, 0, kRulerPx, height() - kRulerPx};
}

// --- Input ------------------------------------------------------------------------------------------

void CutView::changedInteractively() {
  // A change soon after the previous one (allowing for the time the last frame took) is part of a
  // stream: draw it fast and refine when the stream pauses.
  const double window = kRefineDelayMs + lastFrameMs_;
  const qint64 now = clock_();
  if (lastChangeMs_ && now - *lastChangeMs_ < window) interactive_ = true;
  lastChangeMs_ = now;
  refineTimer_.start();
}

void CutView::wheelEvent(QWheelEvent* event) {
  const double notches = event->angleDelta().y() / 120.0;
  if (notches == 0) return;
  changedInteractively();
  zoomBy(std::pow(kZoomStep, notches), event->position());
  event->accept();
}

void CutView::mousePressEvent(QMouseEvent* event) {
  if (cutSplitPress(event)) return;
  if (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton) {
    panning_ = true;
    lastMouse_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  QOpenGLWidget::mousePressEvent(event);
}

void CutView::mouseMoveEvent(QMouseEvent* event) {
  cursor_ = event->position();
  cursorInside_ = true;
  if (cutSplitMove(event)) return;
  if (panning_) {
    const QPointF delta = event->position() - lastMouse_;
    lastMouse_ = event->position();
    center_ -= glm::vec2(static_cast<float>(delta.x() / pixelsPerMm_),
                         static_cast<float>(-delta.y() / pixelsPerMm_));
    framing_ = Framing::Free;
    changedInteractively();
    update();
  }
  updateCursorText(cursor_);
}

void CutView::mouseReleaseEvent(QMouseEvent* event) {
  if (draggingSplit_ && event->button() == Qt::LeftButton) {
    draggingSplit_ = false;
    return;
  }
  if (panning_ && (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton)) {
    panning_ = false;
    unsetCursor();
  }
}

void CutView::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) zoomToFit();
}

void CutView::leaveEvent(QEvent*) {
  cursorInside_ = false;
  if (!lastCursorText_.isEmpty()) {
    lastCursorText_.clear();
    emit cursorPositionChanged(lastCursorText_);
  }
}

void CutView::keyPressEvent(QKeyEvent* event) {
  // The actions' shortcuts take these keys when the window is active; this covers the rest.
  switch (event->key()) {
    case Qt::Key_1:
      zoomToActualSize();
      break;
    case Qt::Key_F:
      zoomToFit();
      break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
      zoomBy(kZoomStep, rect().center());
      break;
    case Qt::Key_Minus:
      zoomBy(1 / kZoomStep, rect().center());
      break;
    default:
      QOpenGLWidget::keyPressEvent(event);
      return;
  }
  event->accept();
}

void CutView::resizeEvent(QResizeEvent* event) {
  QOpenGLWidget::resizeEvent(event);
  reframe();
}

void CutView::updateCursorText(QPointF widgetPos) {
  const QString text = positionText(widgetPos);
  if (text == lastCursorText_) return;
  lastCursorText_ = text;
  emit cursorPositionChanged(text);
}

// --- Drawing ----------------------------------------------------------------------------------------

void CutView::initializeGL() {
  initializeOpenGLFunctions();
  // A new context (the widget moved to another window): the old one's objects go with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &CutView::cleanupGL, Qt::UniqueConnection);
  glError_.clear();
  try {
    // Only the cut polygon is rasterised: Mesa's llvmpipe runs both sides of the fragment shader's
    // "outside the block" branch, so a full-screen triangle costs the full model at every pixel.
    program_ = std::make_unique<WoodProgram>("cut_polygon.vert", "image_plane.frag");
    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  } catch (const std::exception& e) {
    glError_ = QString::fromUtf8(e.what());
    emit glError(glError_);
  }
  uploadedModel_.reset();
}

void CutView::resizeGL(int, int) {}

int CutView::chooseRenderScale() const {
  if (forcedScale_ > 0) return forcedScale_;
  if (!adaptive_ || !interactive_ || msPerMegapixel_ <= 0) return 1;
  const double megapixels = width() * devicePixelRatioF() * height() * devicePixelRatioF() / 1e6;
  const double fullMs = msPerMegapixel_ * megapixels;
  if (fullMs <= budgetMs_) return 1;
  return std::clamp(static_cast<int>(std::ceil(std::sqrt(fullMs / budgetMs_))), 2, 6);
}

void CutView::paintGL() {
  const QColor bg = backgroundColor();
  glClearColor(bg.redF(), bg.greenF(), bg.blueF(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (program_ && glError_.isEmpty() && bounds() && !showsCutAppearance()) {
    const int scale = chooseRenderScale();
    QElapsedTimer timer;
    timer.start();
    try {
      drawWood(scale);
    } catch (const std::exception& e) {  // the board's shader or tables: say why in the view
      glError_ = QString::fromUtf8(e.what());
      emit glError(glError_);
      drawOverlay();
      return;
    }
    glFinish();  // the frame's real cost, for choosing the next frame's resolution
    lastFrameMs_ = timer.nsecsElapsed() / 1e6;
    lastScale_ = scale;
    const double dpr = devicePixelRatioF();
    const double megapixels = std::ceil(width() * dpr / scale) * std::ceil(height() * dpr / scale) / 1e6;
    const double measured = lastFrameMs_ / std::max(1e-3, megapixels);
    msPerMegapixel_ = msPerMegapixel_ <= 0 ? measured : 0.5 * (msPerMegapixel_ + measured);
    emit frameRendered(lastFrameMs_, lastScale_);
  }
  drawOverlay();
}

void CutView::drawWood(int scale) {
  const double dpr = devicePixelRatioF();
  const int fbW = std::max(1, static_cast<int>(std::lround(width() * dpr)));
  const int fbH = std::max(1, static_cast<int>(std::lround(height() * dpr)));
  const int w = (fbW + scale - 1) / scale, h = (fbH + scale - 1) / scale;
  const GLuint target = defaultFramebufferObject();

  if (scale > 1) {
    if (!smallFbo_ || smallSize_ != QSize(w, h)) {
      if (!smallFbo_) glGenFramebuffers(1, &smallFbo_);
      if (!smallColor_) glGenTextures(1, &smallColor_);
      glBindTexture(GL_TEXTURE_2D, smallColor_);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glBindTexture(GL_TEXTURE_2D, 0);
      glBindFramebuffer(GL_FRAMEBUFFER, smallFbo_);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, smallColor_, 0);
      smallSize_ = QSize(w, h);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, smallFbo_);
    const QColor bg = backgroundColor();
    glClearColor(bg.redF(), bg.greenF(), bg.blueF(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glViewport(0, 0, w, h);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_BLEND);  // outside the block the shader gives alpha 0: the background stays
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

  if (boardWood_ && !boardProgram_) {
    boardProgram_ = std::make_unique<WoodProgram>("cut_polygon.vert", "image_plane.frag", WoodSource::Board);
    boardTextures_ = std::make_unique<BoardWoodTextures>();
  }
  QOpenGLShaderProgram& program = boardWood_ ? boardProgram_->program() : program_->program();
  program.bind();
  if (boardWood_) {
    // Texture units from 1 on: unit 0 keeps the model's growth table.
    boardTextures_->upload(*boardWood_, 1);
    boardTextures_->bind(program, 1);
  } else if (uploadedModel_ != model_) {
    program_->setModel(*model_);  // leaves the growth table bound to unit 0
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
    growthTexture_ = static_cast<unsigned>(texture);
    uploadedModel_ = model_;
  }
  glActiveTexture(GL_TEXTURE0);  // QPainter may have moved the unit since
  glBindTexture(GL_TEXTURE_3D, growthTexture_);

  // Each device pixel (X, Y), from the top-left, shows the block point under widget point (X, Y) / dpr.
  const CutPlane& plane = *plane_;
  const double step = scale / (pixelsPerMm_ * dpr);  // mm per rendered pixel
  const glm::vec3 origin = plane.toBlock(planePointAt(QPointF(0, 0)));
  program.setUniformValue("u_planeOrigin", toQt(origin));
  program.setUniformValue("u_pixelRight", toQt(plane.right() * static_cast<float>(step)));
  program.setUniformValue("u_pixelDown", toQt(-plane.up() * static_cast<float>(step)));
  program.setUniformValue("u_imageHeight", static_cast<float>(h));
  program.setUniformValue("u_faceIndex", -1);
  program.setUniformValue("u_blockHalfSize", toQt(model_->block().halfSize()));
  program.setUniformValue("u_clipToBlock", true);
  // The cut polygon in normalized device coordinates of the w x h image, grown by two pixels so that
  // no pixel whose centre is on the wood is missed; the shader clips to the block exactly.
  const std::vector<glm::vec2> polygon = cutPolygon(plane, model_->block());
  glm::vec2 centre(0.0f);
  for (glm::vec2 q : polygon) centre += q;
  centre /= static_cast<float>(std::max<std::size_t>(1, polygon.size()));
  std::vector<float> vertices;
  const double pixelsPerMm = pixelsPerMm_ * dpr / scale;
  for (glm::vec2 q : polygon) {
    const glm::vec2 outward = glm::length(q - centre) > 0 ? glm::normalize(q - centre) : glm::vec2(0.0f);
    const glm::vec2 grown = q + outward * static_cast<float>(2.0 / pixelsPerMm);
    const QPointF px = widgetPointOf(grown) * (dpr / scale);  // rendered pixels from the top-left
    vertices.push_back(static_cast<float>(px.x() / w * 2 - 1));
    vertices.push_back(static_cast<float>(1 - px.y() / h * 2));
  }
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(vertices.size() / 2));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  program.release();
  glDisable(GL_BLEND);

  if (scale > 1) {  // scale up into the widget, top rows aligned
    glBindFramebuffer(GL_READ_FRAMEBUFFER, smallFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, w, h, 0, fbH - h * scale, w * scale, fbH, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
  }
  glViewport(0, 0, fbW, fbH);
}

void CutView::drawOverlay() {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  if (showsCutAppearance()) drawCutAppearance(painter);
  drawCutPhoto(painter);
  const QPolygonF outline = cutOutline();
  if (!outline.isEmpty()) {
    painter.setPen(QPen(QColor(255, 255, 255, 150), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(outline);
  }
  if (showsRingUncertainty()) drawRingUncertainty(painter, outline);
  QFont font = painter.font();
  font.setPixelSize(12);
  painter.setFont(font);
  if (!glError_.isEmpty() || !model_ || !bounds()) {
    painter.setPen(QColor(200, 200, 200));
    const QString text = !glError_.isEmpty() ? tr("OpenGL 3.3 is needed to draw the cut:\n%1").arg(glError_)
                         : !model_           ? tr("No model")
                                             : tr("The cut plane misses the block");
    painter.drawText(rect().adjusted(static_cast<int>(kRulerPx) + 8, 8, -8, -static_cast<int>(kRulerPx) - 8),
                     Qt::AlignCenter | Qt::TextWordWrap, text);
  }
  drawRulers(painter);

  // The scale, as a woodworker reads it off a drawing (1:1, 2:1, 1:2.5), at the end of the ruler.
  const double ratio = pixelsPerMm_ / screenPixelsPerMm();
  const QString scaleText = std::abs(ratio - 1) < 0.005 ? QStringLiteral("1:1")
                            : ratio > 1                 ? QStringLiteral("%1:1").arg(ratio, 0, 'g', 3)
                                                        : QStringLiteral("1:%1").arg(1 / ratio, 0, 'g', 3);
  const QRectF badge = scaleRect();
  painter.setPen(Qt::NoPen);
  painter.fillRect(badge, rulerColor().darker(115));
  painter.setPen(QColor(40, 36, 30));
  painter.drawText(badge, Qt::AlignCenter, scaleText);
}

void CutView::drawRingUncertainty(QPainter& painter, const QPolygonF& outline) {
  const PlaneRect b = *bounds();
  // A quarter of the grid's node spacing (finer shows nothing more: it is trilinear between nodes), and
  // no finer than 8 screen pixels when zoomed out; so a large block costs no more than a small one.
  const glm::vec3 size = model_->block().size();
  const float nodeSpacing = std::max({size.x / float(std::max(1, ringUncertainty_->nodes.x - 1)),
                                      size.y / float(std::max(1, ringUncertainty_->nodes.y - 1)),
                                      size.z / float(std::max(1, ringUncertainty_->nodes.z - 1))});
  const float step = std::max(0.25f * nodeSpacing, static_cast<float>(8.0 / pixelsPerMm_));
  const QImage tint = ringUncertaintyImage(*ringUncertainty_, model_->block(), *plane_, b, step);
  const QPointF topLeft = widgetPointOf({b.min.x, b.max.y}), bottomRight = widgetPointOf({b.max.x, b.min.y});
  painter.save();
  QPainterPath clip;
  clip.addPolygon(outline);
  painter.setClipPath(clip);
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(QRectF(topLeft, bottomRight), tint);
  painter.restore();
  drawRingUncertaintyLegend(painter, rect().adjusted(static_cast<int>(kRulerPx), 0, 0, 0));
}

QRectF CutView::scaleRect() const {
  return {width() - 56.0, height() - kRulerPx, 56.0, kRulerPx};
}

void CutView::drawRulers(QPainter& painter) const {
  const QRectF bottom = bottomRulerRect(), left = leftRulerRect();
  painter.setRenderHint(QPainter::Antialiasing, false);
  painter.setPen(Qt::NoPen);
  painter.setBrush(rulerColor());
  painter.drawRect(bottom);
  painter.drawRect(left);
  const auto b = bounds();
  const glm::vec2 zero = b ? b->min : glm::vec2(0.0f);  // the ruler's 0: the cut's left and bottom edges

  // Ticks every 1 mm at 1:1 on a usual monitor; sparser when zoomed out, finer when zoomed in.
  const double minor = niceStep(3.0 / pixelsPerMm_);
  const double label = std::max(minor * 5, niceStep(34.0 / pixelsPerMm_));
  const double middle = label / 2;
  const QColor ink(40, 36, 30);
  painter.setPen(QPen(ink, 1));
  QFont font = painter.font();
  font.setPixelSize(10);
  painter.setFont(font);
  auto tickLength = [&](double value) {
    auto multiple = [&](double step) { return std::abs(value / step - std::round(value / step)) < 1e-6; };
    return multiple(label) ? 10.0 : multiple(middle) ? 7.0 : 4.0;
  };

  // Bottom: distance from the cut's left edge, along "right".
  {
    const double first = std::floor((planePointAt({kRulerPx, 0}).x - zero.x) / minor) * minor;
    const double last = planePointAt({static_cast<qreal>(width()), 0}).x - zero.x;
    painter.save();
    painter.setClipRect(bottom.adjusted(kRulerPx, 0, 0, 0));
    for (double v = first; v <= last + minor * 0.5; v += minor) {
      const double x = std::round(widgetPointOf({static_cast<float>(v + zero.x), 0}).x()) + 0.5;
      const double len = tickLength(v);
      painter.drawLine(QPointF(x, bottom.top()), QPointF(x, bottom.top() + len));
      if (len == 10.0)
        painter.drawText(QRectF(x - 30, bottom.top() + 10, 60, bottom.height() - 10), Qt::AlignCenter,
                         formatMm(std::round(v / minor) * minor, label));
    }
    painter.restore();
    painter.drawLine(QPointF(kRulerPx, bottom.top() + 0.5), QPointF(width(), bottom.top() + 0.5));
  }
  // Left: distance from the cut's bottom edge, along "up"; labels read from below.
  {
    const double first = std::floor((planePointAt({0, left.bottom()}).y - zero.y) / minor) * minor;
    const double last = planePointAt({0, 0}).y - zero.y;
    painter.save();
    painter.setClipRect(left);
    for (double v = first; v <= last + minor * 0.5; v += minor) {
      const double y = std::round(widgetPointOf({0, static_cast<float>(v + zero.y)}).y()) + 0.5;
      const double len = tickLength(v);
      painter.drawLine(QPointF(left.right() - len, y), QPointF(left.right(), y));
      if (len == 10.0) {
        painter.save();
        painter.translate(left.left() + (left.width() - 10) / 2, y);
        painter.rotate(-90);
        painter.drawText(QRectF(-30, -(left.width() - 10) / 2, 60, left.width() - 10), Qt::AlignCenter,
                         formatMm(std::round(v / minor) * minor, label));
        painter.restore();
      }
    }
    painter.restore();
    painter.drawLine(QPointF(left.right() - 0.5, 0), QPointF(left.right() - 0.5, left.bottom()));
  }
  // The corner: the unit.
  const QRectF corner(0, bottom.top(), kRulerPx, kRulerPx);
  painter.fillRect(corner, rulerColor().darker(115));
  painter.drawText(corner, Qt::AlignCenter, QStringLiteral("mm"));
  painter.setRenderHint(QPainter::Antialiasing, true);
}

}  // namespace kerf
