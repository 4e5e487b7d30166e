#include "viewport3d.hpp"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLFramebufferObject>
#include <QOpenGLPaintDevice>
#include <QOpenGLShaderProgram>
#include <QOpenGLTexture>
#include <QPainter>
#include <QPainterPath>
#include <QVector3D>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gpu/board_wood_textures.hpp"
#include "gpu/gl_helpers.hpp"
#include "gpu/part_mesh_renderer.hpp"
#include "gpu/wood_program.hpp"

namespace kerf {
namespace {

QPointF toPoint(glm::vec3 projected) {
  return {projected.x, projected.y};
}

struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 photoUv;
};

constexpr float kDefaultYaw = 35.0f, kDefaultPitch = 25.0f;
constexpr double kInteractiveTargetMs = 30.0;  // aim of the reduced frames
constexpr int kMaxDivisor = 4;
constexpr double kBandTargetMs = 40.0;  // one band of a progressive refinement
constexpr int kMaxBands = 16;
// Texture units: 0 the growth table, 1 a photo, from 2 on the board's wood (BoardWoodTextures).
constexpr int kBoardWoodUnit = 2;
// The fibre highlight (block.frag): strength and Gaussian width (radians) of the lobe.
constexpr float kSheenStrength = 0.8f, kSheenWidth = 0.2f;

// Gizmo colours.
const QColor kAzimuthColor(120, 205, 130);
const QColor kElevationColor(235, 125, 115);
const QColor kArrowColor(255, 170, 60);

}  // namespace

Viewport3D::Viewport3D(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  if (format.version() < qMakePair(3, 3)) format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  setFormat(format);
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setContextMenuPolicy(Qt::PreventContextMenu);  // right-drag pans
  refineTimer_.setSingleShot(true);
  refineTimer_.setInterval(200);
  connect(&refineTimer_, &QTimer::timeout, this, &Viewport3D::refine);
  camera_.setAngles(kDefaultYaw, kDefaultPitch);
  gizmo_.setBlock(block_);
}

Viewport3D::~Viewport3D() {
  // As in CutView: the context outlives this destructor, so its signal must not reach releaseGl.
  if (context()) disconnect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport3D::releaseGl);
  releaseGl();
}

void Viewport3D::releaseGl() {
  if (!glFunctions_) return;
  makeCurrent();
  reducedFbo_.reset();
  fullFbo_.reset();
  for (auto& texture : photoTextures_) texture.reset();
  for (auto& texture : faceAppearanceTextures_) texture.reset();
  cutAppearanceTexture_.reset();
  appearanceDirty_ = true;
  blockProgram_.reset();
  backgroundProgram_.reset();
  if (partRenderer_) partRenderer_->release();
  partDirty_ = true;
  boardProgram_.reset();
  boardTextures_.reset();
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteVertexArrays(1, &capArray_);
  glDeleteVertexArrays(1, &emptyArray_);
  glDeleteBuffers(1, &vertexBuffer_);
  glDeleteBuffers(1, &capBuffer_);
  glReady_ = false;
  glFunctions_ = false;
  doneCurrent();
}

// --- Public setters ----------------------------------------------------------------------------------

void Viewport3D::setModel(std::shared_ptr<const WoodModel> model) {
  const bool first = !model_;
  model_ = std::move(model);
  modelDirty_ = true;
  if (model_ && model_->block().size() != block_.size()) {
    block_ = model_->block();
    gizmo_.setBlock(block_);
    camera_.fit(block_.halfSize());
    autoFrame_ = true;
  }
  sceneChanged(!first && model_);
}

void Viewport3D::setBoardWood(std::shared_ptr<const BoardWood> wood) {
  if (wood == boardWood_) return;
  const bool interactive = wood && boardWood_;  // a board moving or a knot slider: draw fast, refine later
  boardWood_ = std::move(wood);
  sceneChanged(interactive);
}

void Viewport3D::setCutPlane(const CutPlaneSetting& setting) {
  if (gizmo_.dragging() || setting == gizmo_.setting()) return;
  gizmo_.setSetting(setting);
  if (cutEnabled_) sceneChanged(true);
}

void Viewport3D::setCutEnabled(bool enabled) {
  if (enabled == cutEnabled_) return;
  cutEnabled_ = enabled;
  if (!enabled && gizmo_.dragging()) {
    gizmo_.cancelDrag();
    dragMode_ = DragMode::None;
  }
  setHover(CutGizmo::Handle::None);
  sceneChanged(false);
}

void Viewport3D::setCutSide(CutSide side) {
  if (side == cutSide_) return;
  cutSide_ = side;
  if (cutEnabled_) sceneChanged(false);
}

void Viewport3D::setCutHandlesVisible(bool visible) {
  handlesVisible_ = visible;
  update();
}

void Viewport3D::setFiberHighlight(float strength) {
  if (!std::isfinite(strength) || strength == fiberHighlight_) return;
  fiberHighlight_ = std::max(strength, 0.0f);
  sceneChanged(false);
}

void Viewport3D::setFacePhotos(const std::array<QImage, 6>& photos) {
  photos_ = photos;
  photosDirty_ = true;
  if (showPhotos_) sceneChanged(false);
}

void Viewport3D::setFaceAppearance(std::shared_ptr<const WoodModel> forModel,
                                   const std::array<QImage, 6>& faces) {
  faceAppearanceModel_ = std::move(forModel);
  faceAppearance_ = faces;
  appearanceDirty_ = true;
  sceneChanged(false);
}

void Viewport3D::setCutAppearance(const CutAppearance& cut) {
  cutAppearance_ = cut;
  appearanceDirty_ = true;
  if (cutEnabled_) sceneChanged(false);
}

bool Viewport3D::showsFaceAppearance() const {
  return model_ && faceAppearanceModel_ == model_ && !boardWood_;
}

bool Viewport3D::showsCutAppearance() const {
  return cutEnabled_ && model_ && cutAppearance_.model == model_ && !boardWood_ &&
         cutAppearance_.plane == gizmo_.setting() && !cutAppearance_.surface.image.isNull();
}

void Viewport3D::setPart(std::shared_ptr<const Mesh> placedMesh) {
  part_ = std::move(placedMesh);
  partDirty_ = true;
  sceneChanged(false);
}

void Viewport3D::setShowPhotos(bool show) {
  if (show == showPhotos_) return;
  showPhotos_ = show;
  sceneChanged(false);
}

void Viewport3D::resetCamera() {
  camera_.setAngles(kDefaultYaw, kDefaultPitch);
  camera_.fit(block_.halfSize());
  autoFrame_ = true;
  sceneChanged(false);
}

void Viewport3D::fitCamera() {
  camera_.fit(block_.halfSize());
  autoFrame_ = true;
  sceneChanged(false);
}

void Viewport3D::setCamera(const OrbitCamera& camera) {
  camera_ = camera;
  camera_.setViewportSize(glm::vec2(std::max(width(), 1), std::max(height(), 1)));
  autoFrame_ = false;
  sceneChanged(false);
}

void Viewport3D::setReducedResolutionDivisor(int divisor) {
  fixedDivisor_ = std::clamp(divisor, 0, kMaxDivisor);
  update();
}

void Viewport3D::setRefineDelayMs(int ms) {
  refineTimer_.setInterval(std::max(ms, 0));
}

void Viewport3D::refineNow() {
  refineTimer_.stop();
  interactive_ = false;
  reducedValid_ = false;  // no progressive bands: the next frame is complete
  update();
}

// --- Change tracking ---------------------------------------------------------------------------------

void Viewport3D::sceneChanged(bool interactive) {
  reducedValid_ = false;
  fullBandsDone_ = 0;
  if (interactive) {
    interactive_ = true;
    refineTimer_.start();
  } else if (!refineTimer_.isActive()) {
    interactive_ = false;
  }
  update();
}

void Viewport3D::refine() {
  interactive_ = false;
  update();
}

int Viewport3D::chooseDivisor() const {
  if (fixedDivisor_ > 0) return fixedDivisor_;
  if (msPerMegapixel_ < 0.0) return 2;
  const double megapixels = width() * devicePixelRatioF() * height() * devicePixelRatioF() * 1e-6;
  const double fullMs = msPerMegapixel_ * megapixels;
  return std::clamp(static_cast<int>(std::ceil(std::sqrt(fullMs / kInteractiveTargetMs) - 0.05)), 1,
                    kMaxDivisor);
}

int Viewport3D::chooseBandCount(QSize full) const {
  if (msPerMegapixel_ < 0.0) return 4;
  const double fullMs = msPerMegapixel_ * full.width() * full.height() * 1e-6;
  return std::clamp(static_cast<int>(std::ceil(fullMs / kBandTargetMs)), 1, kMaxBands);
}

void Viewport3D::noteCost(double ms, double pixels) {
  if (pixels < 1.0) return;
  const double perMp = ms / (pixels * 1e-6);
  msPerMegapixel_ = msPerMegapixel_ < 0.0 ? perMp : 0.6 * msPerMegapixel_ + 0.4 * perMp;
}

// --- OpenGL ------------------------------------------------------------------------------------------

void Viewport3D::initializeGL() {
  if (!initializeOpenGLFunctions()) {
    qWarning("Viewport3D: OpenGL 3.3 core is not available (got %d.%d)", context()->format().majorVersion(),
             context()->format().minorVersion());
    return;
  }
  glFunctions_ = true;
  rendererName_ = QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  try {
    blockProgram_ = std::make_unique<WoodProgram>("block.vert", "block.frag");
  } catch (const std::exception& e) {
    qWarning("Viewport3D: %s", e.what());
    failure_ = tr("The 3D view's shaders did not build (see the log).");
    return;
  }
  backgroundProgram_ = std::make_unique<QOpenGLShaderProgram>();
  if (!backgroundProgram_->addShaderFromSourceCode(
          QOpenGLShader::Vertex, "#version 330 core\n" + WoodProgram::shaderFile("image_plane.vert")) ||
      !backgroundProgram_->addShaderFromSourceCode(
          QOpenGLShader::Fragment,
          "#version 330 core\n" + WoodProgram::shaderFile("block_background.frag")) ||
      !backgroundProgram_->link()) {
    qWarning("Viewport3D: background shader: %s", qPrintable(backgroundProgram_->log()));
    failure_ = tr("The 3D view's shaders did not build (see the log).");
    return;
  }
  glGenVertexArrays(1, &vertexArray_);
  glGenVertexArrays(1, &capArray_);
  glGenVertexArrays(1, &emptyArray_);
  glGenBuffers(1, &vertexBuffer_);
  glGenBuffers(1, &capBuffer_);
  for (unsigned vao : {vertexArray_, capArray_}) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vao == vertexArray_ ? vertexBuffer_ : capBuffer_);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, photoUv)));
  }
  glBindVertexArray(0);
  glReady_ = true;
  modelDirty_ = true;
  photosDirty_ = true;
  reducedValid_ = false;
  fullBandsDone_ = 0;
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport3D::releaseGl, Qt::DirectConnection);
}

void Viewport3D::resizeGL(int w, int h) {
  camera_.setViewportSize(glm::vec2(std::max(w, 1), std::max(h, 1)));
  if (autoFrame_) camera_.fit(block_.halfSize());
  sceneChanged(fullFbo_ != nullptr || reducedFbo_ != nullptr);  // the first size is not an interaction
}

void Viewport3D::uploadGeometry() {
  // Six faces, two triangles each, counter-clockwise seen from outside; photo coordinates by
  // Block::blockToImage (normalised to 0..1, rows downward as in the image).
  std::vector<Vertex> vertices;
  for (FaceId id : kAllFaces) {
    const FaceFrame f = block_.face(id);
    const glm::vec3 r = 0.5f * f.widthMm * f.right, d = 0.5f * f.heightMm * f.down;
    std::array<glm::vec3, 4> corners{f.center - r - d, f.center + r - d, f.center + r + d, f.center - r + d};
    if (glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), f.normal) < 0.0f)
      std::swap(corners[1], corners[3]);
    for (int i : {0, 1, 2, 0, 2, 3})
      vertices.push_back({corners[i], f.normal, block_.blockToImage(id, corners[i], {1, 1})});
  }
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

namespace {

// An image as a face or cut texture (mipmapped; null for a null image), at most the GL's size.
std::unique_ptr<QOpenGLTexture> surfaceTexture(QImage image, int maxSize) {
  if (image.isNull()) return nullptr;
  if (image.width() > maxSize || image.height() > maxSize)
    image = image.scaled(maxSize, maxSize, Qt::KeepAspectRatio, Qt::SmoothTransformation);
  // QOpenGLTexture keeps the image's first row at t = 0, as blockToImage counts rows.
  auto texture = std::make_unique<QOpenGLTexture>(image.convertToFormat(QImage::Format_RGBA8888),
                                                  QOpenGLTexture::GenerateMipMaps);
  texture->setMinMagFilters(QOpenGLTexture::LinearMipMapLinear, QOpenGLTexture::Linear);
  texture->setWrapMode(QOpenGLTexture::ClampToEdge);
  return texture;
}

int maxTextureSize(QOpenGLFunctions_3_3_Core& gl) {
  GLint maxSize = 4096;
  gl.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  return maxSize;
}

}  // namespace

void Viewport3D::uploadPhotos() {
  const int maxSize = maxTextureSize(*this);
  for (int i = 0; i < 6; ++i) photoTextures_[i] = surfaceTexture(photos_[i], maxSize);
  photosDirty_ = false;
}

void Viewport3D::uploadAppearance() {
  const int maxSize = maxTextureSize(*this);
  for (int i = 0; i < 6; ++i) faceAppearanceTextures_[i] = surfaceTexture(faceAppearance_[i], maxSize);
  cutAppearanceTexture_ = surfaceTexture(cutAppearance_.surface.image, maxSize);
  appearanceDirty_ = false;
}

void Viewport3D::paintGL() {
  QElapsedTimer clock;
  clock.start();
  lastRenderedScene_ = false;
  if (!glReady_) {
    if (glFunctions_) {  // say why instead of showing an undefined framebuffer
      glClearColor(0.2f, 0.21f, 0.23f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      QOpenGLPaintDevice device(size() * devicePixelRatioF());
      device.setDevicePixelRatio(devicePixelRatioF());
      QPainter painter(&device);
      painter.setPen(QColor(220, 220, 220));
      painter.drawText(rect(), Qt::AlignCenter, failure_);
    }
    return;
  }
  const qreal dpr = devicePixelRatioF();
  const QSize full(std::max(1, qRound(width() * dpr)), std::max(1, qRound(height() * dpr)));

  if (modelDirty_ && model_) {
    blockProgram_->program().bind();
    blockProgram_->setModel(*model_);
    glActiveTexture(GL_TEXTURE0);
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &bound);
    growthTexture_ = static_cast<unsigned>(bound);
    blockProgram_->program().release();
    uploadGeometry();
    modelDirty_ = false;
  }
  if (photosDirty_) uploadPhotos();
  if (appearanceDirty_) uploadAppearance();
  if (partDirty_) {
    if (!partRenderer_) partRenderer_ = std::make_unique<PartMeshRenderer>();
    if (part_) partRenderer_->upload(*part_);
    partDirty_ = false;
  }
  if (boardWood_) {
    try {
      if (!boardProgram_) {
        boardProgram_ = std::make_unique<WoodProgram>("block.vert", "block.frag", WoodSource::Board);
        boardTextures_ = std::make_unique<BoardWoodTextures>();
      }
      boardTextures_->upload(*boardWood_, kBoardWoodUnit);
    } catch (const std::exception& e) {  // say why instead of showing the wrong wood
      failure_ = tr("The board's wood cannot be drawn: %1").arg(QString::fromUtf8(e.what()));
      glReady_ = false;
      update();
      return;
    }
  }

  const int divisor = interactive_ ? chooseDivisor() : 1;
  const GLuint screen = defaultFramebufferObject();
  if (divisor > 1) {
    // Interacting: the whole picture at a reduced resolution, scaled up.
    const QSize size((full.width() + divisor - 1) / divisor, (full.height() + divisor - 1) / divisor);
    if (!reducedFbo_ || reducedFbo_->size() != size) {
      reducedFbo_ =
          std::make_unique<QOpenGLFramebufferObject>(size, QOpenGLFramebufferObject::CombinedDepthStencil);
      reducedValid_ = false;
    }
    if (!reducedValid_ || reducedDivisor_ != divisor) {
      QElapsedTimer sceneClock;
      sceneClock.start();
      renderScene(*reducedFbo_, 0, size.height());
      glFinish();  // the compositor waits for it anyway; this makes the cost measurable
      noteCost(sceneClock.nsecsElapsed() * 1e-6, size.width() * size.height());
      reducedValid_ = true;
      reducedDivisor_ = divisor;
      lastRenderedScene_ = true;
    }
    lastDivisor_ = divisor;
  } else {
    if (!fullFbo_ || fullFbo_->size() != full) {
      fullFbo_ =
          std::make_unique<QOpenGLFramebufferObject>(full, QOpenGLFramebufferObject::CombinedDepthStencil);
      fullBandsDone_ = 0;
    }
    // After an interaction (a reduced picture is on screen) the full picture is drawn band by band, top
    // down, one band per frame; otherwise all at once.
    const bool progressive = reducedValid_ && reducedFbo_;
    if (fullBandsDone_ == 0) fullBandCount_ = progressive ? chooseBandCount(full) : 1;
    if (fullBandsDone_ < fullBandCount_) {
      const int bandRows = (full.height() + fullBandCount_ - 1) / fullBandCount_;
      const int bandsNow = progressive ? 1 : fullBandCount_ - fullBandsDone_;
      const int top = full.height() - fullBandsDone_ * bandRows;
      const int bottom = std::max(0, full.height() - (fullBandsDone_ + bandsNow) * bandRows);
      QElapsedTimer sceneClock;
      sceneClock.start();
      renderScene(*fullFbo_, bottom, top);
      glFinish();
      noteCost(sceneClock.nsecsElapsed() * 1e-6, double(full.width()) * (top - bottom));
      fullBandsDone_ += bandsNow;
      if (bottom == 0) fullBandsDone_ = fullBandCount_;
      lastRenderedScene_ = true;
      if (fullBandsDone_ < fullBandCount_) QTimer::singleShot(0, this, qOverload<>(&QWidget::update));
    }
    lastDivisor_ = fullBandsDone_ >= fullBandCount_ ? 1 : reducedDivisor_;
  }

  // Compose: the reduced picture scaled up, and the finished rows of the full one over it.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, screen);
  if (lastDivisor_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, reducedFbo_->handle());
    glBlitFramebuffer(0, 0, reducedFbo_->width(), reducedFbo_->height(), 0, 0, full.width(), full.height(),
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
  }
  if (divisor == 1 && fullFbo_) {
    const int bandRows = (full.height() + fullBandCount_ - 1) / fullBandCount_;
    const int bottom = std::max(0, full.height() - fullBandsDone_ * bandRows);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fullFbo_->handle());
    glBlitFramebuffer(0, bottom, full.width(), full.height(), 0, bottom, full.width(), full.height(),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, screen);
  glViewport(0, 0, full.width(), full.height());
  {
    // A paint device on the bound framebuffer rather than `this`: QWidget::grab()/render() redirect
    // painting on the widget, which would lose the overlay in screenshots of the whole window.
    QOpenGLPaintDevice device(full);
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    drawOverlay(painter);
  }
  if (finishFrames_) glFinish();
  emit frameRendered(clock.nsecsElapsed() * 1e-6);
}

void Viewport3D::renderScene(QOpenGLFramebufferObject& target, int rowBegin, int rowEnd) {
  target.bind();
  const QSize size = target.size();
  glViewport(0, 0, size.width(), size.height());
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, rowBegin, size.width(), rowEnd - rowBegin);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  backgroundProgram_->bind();
  backgroundProgram_->setUniformValue("u_top", QVector3D(0.33f, 0.345f, 0.37f));
  backgroundProgram_->setUniformValue("u_bottom", QVector3D(0.16f, 0.17f, 0.185f));
  backgroundProgram_->setUniformValue("u_height", static_cast<float>(size.height()));
  glBindVertexArray(emptyArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  backgroundProgram_->release();
  glClear(GL_DEPTH_BUFFER_BIT);

  if (model_ && growthTexture_ != 0) {
    QOpenGLShaderProgram& program = sceneProgram();
    program.bind();
    if (boardWood_) boardTextures_->bind(program, kBoardWoodUnit);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_3D, growthTexture_);
    const glm::mat4 viewProjection = camera_.viewProjection();
    glUniformMatrix4fv(program.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                       glm::value_ptr(viewProjection));
    const glm::vec3 f = camera_.forward(), r = camera_.right(), u = camera_.up();
    program.setUniformValue("u_eye", toQt(camera_.eye()));
    program.setUniformValue("u_keyLight", toQt(glm::normalize(-0.25f * r + 0.5f * u - 0.85f * f)));
    program.setUniformValue("u_fillLight", toQt(glm::normalize(0.55f * r - 0.45f * u - 0.7f * f)));
    program.setUniformValue("u_blockHalfSize", toQt(block_.halfSize()));
    const CutPlaneSetting& cut = gizmo_.setting();
    const bool cutOn = cutEnabled_ && std::isfinite(cut.offsetMm);
    program.setUniformValue("u_cutEnabled", cutOn);
    program.setUniformValue("u_cutNormal", toQt(cut.normal()));
    program.setUniformValue("u_cutOffset", cut.offsetMm);
    program.setUniformValue("u_sheenStrength", kSheenStrength * fiberHighlight_);
    program.setUniformValue("u_sheenWidth", kSheenWidth);
    program.setUniformValue("u_photo", 1);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    if (part_) {
      drawPart();  // the part, then the whole block ghosted around it
    } else {
      drawBlock(false);
    }
    if (cutOn && !part_) {
      drawCap();
      if (cutSide_ == CutSide::Ghost) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // alpha stays 1
        glDepthMask(GL_FALSE);
        drawBlock(true);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
      }
    }
    program.release();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
  }
  glBindVertexArray(0);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
}

QOpenGLShaderProgram& Viewport3D::sceneProgram() {
  return boardWood_ && boardProgram_ ? boardProgram_->program() : blockProgram_->program();
}

void Viewport3D::drawBlock(bool ghost) {
  QOpenGLShaderProgram& program = sceneProgram();
  program.setUniformValue("u_pass", ghost ? 2 : 0);
  glBindVertexArray(vertexArray_);
  for (int face = 0; face < 6; ++face) {
    const bool photo = showPhotos_ && !ghost && photoTextures_[face];
    const bool own = !photo && !ghost && showsFaceAppearance() && faceAppearanceTextures_[face];
    program.setUniformValue("u_faceIndex", face);
    program.setUniformValue("u_showPhoto", photo || own);
    if (photo) photoTextures_[face]->bind(1);
    if (own) faceAppearanceTextures_[face]->bind(1);
    glDrawArrays(GL_TRIANGLES, face * 6, 6);
  }
  glActiveTexture(GL_TEXTURE0);
}

void Viewport3D::drawPart() {
  QOpenGLShaderProgram& program = sceneProgram();  // in log mode the part shows the board's wood
  program.setUniformValue("u_pass", 3);
  program.setUniformValue("u_faceIndex", -1);
  program.setUniformValue("u_showPhoto", false);
  // The whole part, uncut: a mesh is a surface, so a cut would show its inside faces, not the wood
  // inside the part.
  program.setUniformValue("u_cutEnabled", false);
  glDisable(GL_CULL_FACE);  // files wind their triangles either way; block.frag turns the normal to the eye
  partRenderer_->draw();
  glEnable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // alpha stays 1
  glDepthMask(GL_FALSE);
  drawBlock(true);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void Viewport3D::drawCap() {
  const std::vector<glm::vec3>& polygon = gizmo_.polygon();
  if (polygon.size() < 3) return;
  const glm::vec3 n = gizmo_.normal();
  std::vector<Vertex> vertices;
  const bool own = showsCutAppearance() && cutAppearanceTexture_;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    for (std::size_t k : {std::size_t{0}, i, i + 1})
      vertices.push_back(
          {polygon[k], n, own ? cutAppearance_.surface.textureCoordinates(polygon[k]) : glm::vec2(0.0f)});
  glBindBuffer(GL_ARRAY_BUFFER, capBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  QOpenGLShaderProgram& program = sceneProgram();
  program.setUniformValue("u_pass", 1);
  program.setUniformValue("u_faceIndex", -1);
  program.setUniformValue("u_showPhoto", own);
  if (own) cutAppearanceTexture_->bind(1);
  glEnable(GL_POLYGON_OFFSET_FILL);  // wins over a face it lies on
  glPolygonOffset(-1.0f, -1.0f);
  glBindVertexArray(capArray_);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  glDisable(GL_POLYGON_OFFSET_FILL);
  glActiveTexture(GL_TEXTURE0);
}

// --- Overlay (QPainter, full resolution) -------------------------------------------------------------

void Viewport3D::drawOverlay(QPainter& painter) {
  painter.setRenderHint(QPainter::Antialiasing);
  const float w = static_cast<float>(width()), h = static_cast<float>(height());

  if (!model_) {
    painter.setPen(QColor(200, 200, 200));
    painter.drawText(rect(), Qt::AlignCenter, tr("No wood model"));
    return;
  }

  // Face letters at the centres of the faces turned towards the viewer.
  QFont font = painter.font();
  font.setPixelSize(12);
  font.setBold(true);
  painter.setFont(font);
  const glm::vec3 eye = camera_.eye();
  for (FaceId id : kAllFaces) {
    const FaceFrame f = block_.face(id);
    if (glm::dot(eye - f.center, f.normal) <= 0.0f) continue;
    const float facing = glm::dot(glm::normalize(eye - f.center), f.normal);
    if (facing < 0.25f) continue;
    if (cutEnabled_ && !part_ && cutSide_ == CutSide::Hide &&
        glm::dot(f.center, gizmo_.normal()) > gizmo_.setting().offsetMm)
      continue;
    const glm::vec3 p = camera_.project(f.center + f.normal * 0.01f);
    if (p.z <= 0.0f) continue;
    const QRectF badge(p.x - 9, p.y - 9, 18, 18);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 20, 20, static_cast<int>(60 * facing)));
    painter.drawEllipse(badge);
    painter.setPen(QColor(255, 255, 255, static_cast<int>(150 * facing)));
    painter.drawText(badge, Qt::AlignCenter, QString(QChar(faceLetter(id))));
  }

  // Orientation triad, bottom left.
  {
    const QPointF origin(34, h - 34);
    struct Axis {
      glm::vec3 dir;
      QColor color;
      const char* name;
    };
    std::array<Axis, 3> axes{{{{1, 0, 0}, QColor(230, 90, 80), "x"},
                              {{0, 1, 0}, QColor(120, 200, 90), "y"},
                              {{0, 0, 1}, QColor(90, 140, 235), "z"}}};
    std::sort(axes.begin(), axes.end(), [&](const Axis& a, const Axis& b) {
      return glm::dot(a.dir, camera_.forward()) > glm::dot(b.dir, camera_.forward());
    });
    for (const Axis& a : axes) {
      const QPointF tip =
          origin + 22.0 * QPointF(glm::dot(a.dir, camera_.right()), -glm::dot(a.dir, camera_.up()));
      painter.setPen(QPen(a.color, 2.0, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(origin, tip);
      painter.drawText(QRectF(tip.x() - 8 + (tip.x() - origin.x()) * 0.35,
                              tip.y() - 8 + (tip.y() - origin.y()) * 0.35, 16, 16),
                       Qt::AlignCenter, a.name);
    }
  }

  if (!cutEnabled_ || !handlesVisible_ || part_ || !gizmo_.meetsBlock()) return;
  const CutGizmo::Handle active = gizmo_.dragging() ? gizmo_.dragHandle() : hover_;
  const float centreDepth = camera_.project(gizmo_.pivot()).z;

  for (CutGizmo::Handle ring : {CutGizmo::Handle::AzimuthRing, CutGizmo::Handle::ElevationRing}) {
    const bool hot = active == ring;
    QColor color = ring == CutGizmo::Handle::AzimuthRing ? kAzimuthColor : kElevationColor;
    if (hot) color = color.lighter(125);
    const std::vector<glm::vec3> line = gizmo_.ringPolyline(ring, 120);
    for (int front = 0; front < 2; ++front) {
      QPainterPath path;
      bool open = false;
      for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const glm::vec3 a = camera_.project(line[i]), b = camera_.project(line[i + 1]);
        const bool isFront = 0.5f * (a.z + b.z) <= centreDepth;
        if (a.z <= 0.0f || b.z <= 0.0f || isFront != (front == 1)) {
          open = false;
          continue;
        }
        if (!open) path.moveTo(toPoint(a));
        path.lineTo(toPoint(b));
        open = true;
      }
      QColor c = color;
      c.setAlpha(front ? (hot ? 255 : 190) : (hot ? 140 : 70));
      painter.setPen(
          QPen(c, front ? (hot ? 3.0 : 1.6) : 1.2, front ? Qt::SolidLine : Qt::DashLine, Qt::RoundCap));
      painter.setBrush(Qt::NoBrush);
      painter.drawPath(path);
    }
  }

  // The normal arrow.
  {
    const bool hot = active == CutGizmo::Handle::Arrow || active == CutGizmo::Handle::Surface;
    const glm::vec3 a = camera_.project(gizmo_.pivot()), b = camera_.project(gizmo_.arrowTip());
    if (a.z > 0.0f && b.z > 0.0f) {
      QColor c = hot ? kArrowColor.lighter(120) : kArrowColor;
      painter.setPen(QPen(QColor(20, 20, 20, 110), hot ? 4.5 : 3.5, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(toPoint(a), toPoint(b));
      painter.setPen(QPen(c, hot ? 2.5 : 1.8, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(toPoint(a), toPoint(b));
      painter.setPen(QPen(QColor(20, 20, 20, 160), 1.0));
      painter.setBrush(c);
      painter.drawEllipse(toPoint(b), hot ? 6.0 : 5.0, hot ? 6.0 : 5.0);
      painter.drawEllipse(toPoint(a), 2.5, 2.5);
    }
  }

  // While dragging: the value being set, next to the cursor.
  if (gizmo_.dragging()) {
    const CutPlaneSetting& s = gizmo_.setting();
    QString text;
    if (gizmo_.dragHandle() == CutGizmo::Handle::Surface || gizmo_.dragHandle() == CutGizmo::Handle::Arrow)
      text = tr("offset %1 mm").arg(s.offsetMm, 0, 'f', 1);
    else
      text = tr("azimuth %1°  elevation %2°").arg(s.azimuthDeg, 0, 'f', 1).arg(s.elevationDeg, 0, 'f', 1);
    font.setBold(false);
    painter.setFont(font);
    const QRectF box = QFontMetricsF(font).boundingRect(text).adjusted(-6, -3, 6, 3);
    QPointF at = lastMouse_ + QPointF(16, 20);
    at.setX(std::min<double>(at.x(), w - box.width() - 4));
    at.setY(std::min<double>(at.y(), h - box.height() - 4));
    const QRectF r(at, box.size());
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 20, 22, 200));
    painter.drawRoundedRect(r, 4, 4);
    painter.setPen(QColor(240, 240, 240));
    painter.drawText(r, Qt::AlignCenter, text);
  }
}

// --- Interaction -------------------------------------------------------------------------------------

void Viewport3D::setHover(CutGizmo::Handle handle) {
  if (handle == hover_) return;
  hover_ = handle;
  updateCursor();
  update();  // overlay only: the wood picture is reused
}

void Viewport3D::updateCursor() {
  if (dragMode_ == DragMode::Cut)
    setCursor(Qt::ClosedHandCursor);
  else if (dragMode_ == DragMode::Orbit || dragMode_ == DragMode::Pan)
    setCursor(Qt::SizeAllCursor);
  else if (hover_ == CutGizmo::Handle::Surface || hover_ == CutGizmo::Handle::Arrow)
    setCursor(Qt::SizeVerCursor);
  else if (hover_ != CutGizmo::Handle::None)
    setCursor(Qt::OpenHandCursor);
  else
    unsetCursor();
}

void Viewport3D::mousePressEvent(QMouseEvent* event) {
  lastMouse_ = event->position();
  const glm::vec2 px(event->position().x(), event->position().y());
  if (dragMode_ != DragMode::None) return;
  if (event->button() == Qt::LeftButton) {
    const CutGizmo::Handle handle = cutEnabled_ && handlesVisible_ && model_ && !part_
                                        ? gizmo_.pick(camera_, px)
                                        : CutGizmo::Handle::None;
    if (handle != CutGizmo::Handle::None && gizmo_.beginDrag(handle, camera_, px)) {
      emittedDuringDrag_ = false;
      dragMode_ = DragMode::Cut;
    } else {
      dragMode_ = DragMode::Orbit;
    }
  } else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
    dragMode_ = DragMode::Pan;
  }
  dragButton_ = event->button();
  updateCursor();
  update();
  event->accept();
}

void Viewport3D::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  const glm::vec2 px(pos.x(), pos.y());
  const glm::vec2 delta(pos.x() - lastMouse_.x(), pos.y() - lastMouse_.y());
  lastMouse_ = pos;
  switch (dragMode_) {
    case DragMode::None:
      setHover(cutEnabled_ && handlesVisible_ && model_ && !part_ ? gizmo_.pick(camera_, px)
                                                                  : CutGizmo::Handle::None);
      break;
    case DragMode::Orbit:
      camera_.orbit(delta);
      sceneChanged(true);
      break;
    case DragMode::Pan:
      camera_.pan(delta);
      autoFrame_ = false;
      sceneChanged(true);
      break;
    case DragMode::Cut: {
      const CutPlaneSetting before = gizmo_.setting();
      const CutPlaneSetting s = gizmo_.drag(camera_, px, event->modifiers() & Qt::ShiftModifier);
      if (s != before) {
        sceneChanged(true);
        emittedDuringDrag_ = true;
        emit cutPlaneEdited(s, false);
      } else {
        update();  // the readout follows the cursor
      }
      break;
    }
  }
  event->accept();
}

void Viewport3D::mouseReleaseEvent(QMouseEvent* event) {
  lastMouse_ = event->position();
  if (dragMode_ != DragMode::None && event->button() != dragButton_) return;  // another button
  if (dragMode_ == DragMode::Cut) {
    const CutPlaneSetting start = gizmo_.dragStartSetting();
    gizmo_.endDrag();
    dragMode_ = DragMode::None;
    // Closes the edit the intermediate signals opened (even when the plane ended where it began).
    if (emittedDuringDrag_ || gizmo_.setting() != start) emit cutPlaneEdited(gizmo_.setting(), true);
  } else {
    dragMode_ = DragMode::None;
  }
  const glm::vec2 px(lastMouse_.x(), lastMouse_.y());
  hover_ =
      cutEnabled_ && handlesVisible_ && model_ && !part_ ? gizmo_.pick(camera_, px) : CutGizmo::Handle::None;
  updateCursor();
  update();
  event->accept();
}

void Viewport3D::wheelEvent(QWheelEvent* event) {
  const float steps = event->angleDelta().y() / 120.0f;
  if (steps != 0.0f) {
    camera_.zoom(steps, glm::vec2(event->position().x(), event->position().y()));
    autoFrame_ = false;
    sceneChanged(true);
  }
  event->accept();
}

void Viewport3D::keyPressEvent(QKeyEvent* event) {
  const bool ctrl = event->modifiers() & Qt::ControlModifier;
  switch (event->key()) {
    case Qt::Key_F:
      fitCamera();
      break;
    case Qt::Key_1:
      camera_.setView(ctrl ? OrbitCamera::View::Back : OrbitCamera::View::Front);
      sceneChanged(false);
      break;
    case Qt::Key_3:
      camera_.setView(ctrl ? OrbitCamera::View::Left : OrbitCamera::View::Right);
      sceneChanged(false);
      break;
    case Qt::Key_7:
      camera_.setView(ctrl ? OrbitCamera::View::Bottom : OrbitCamera::View::Top);
      sceneChanged(false);
      break;
    case Qt::Key_Home:
      resetCamera();
      break;
    case Qt::Key_Escape:
      if (dragMode_ == DragMode::Cut) {
        const CutPlaneSetting start = gizmo_.dragStartSetting();
        const bool changed = emittedDuringDrag_ || gizmo_.setting() != start;
        gizmo_.cancelDrag();
        dragMode_ = DragMode::None;
        updateCursor();
        sceneChanged(false);
        if (changed) emit cutPlaneEdited(start, true);
        break;
      }
      QOpenGLWidget::keyPressEvent(event);
      return;
    default:
      QOpenGLWidget::keyPressEvent(event);
      return;
  }
  event->accept();
}

void Viewport3D::leaveEvent(QEvent* event) {
  if (dragMode_ == DragMode::None) setHover(CutGizmo::Handle::None);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace kerf
