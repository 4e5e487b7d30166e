#pragma once
// The editor's live 3D view: the block, textured per fragment by the GLSL wood model
// (shaders/wood_model.glsl via shaders/block.vert/.frag), lit like finished wood (diffuse, a soft clear
// coat highlight and the fibre highlight of Liu et al. 2016 Sec. 2/4.3, after Marschner et al. 2005),
// with an optional cut plane and the face photos projected onto the faces for comparison.
//
// Log mode (setBoardWood): the faces and the cut surface show a board cut from a log, its knot model
// evaluated per fragment (shaders/board_wood.glsl; knots culled per cell of a coarse grid over the board).
//
// Cut: with the cut enabled, the part of the block on the side the normal points to is hidden or drawn
// ghosted (CutSide), and the cut surface is drawn with the model (no face tint). The view shows handles
// on the plane (see CutGizmo): left-drag on the cut surface or the arrow moves the plane along its normal,
// dragging a ring turns it (horizontal ring: azimuth, vertical ring: elevation, about the cut surface's
// centre); the dragged angle snaps to a principal plane within 3 degrees, and to 15 degree steps with
// Shift held (Shift also rounds offsets to whole mm); Esc during a drag puts the plane back.
// While dragging, the view applies the new plane itself at once and emits cutPlaneEdited(setting,
// false) for every step and cutPlaneEdited(setting, true) once on release (or on Esc, with the plane it
// started from; nothing when the plane never changed). setCutPlane() during a drag is ignored (the
// editor echoing the signal back is harmless); it never emits.
//
// Part (issue 7): setPart() shows a placed mesh inside the block, coloured per fragment by the same wood
// model (the block's wood where the part would be cut from it), with the block drawn ghosted around it
// (gpu/part_mesh_renderer.hpp). The cut is not applied while a part is shown.
//
// Navigation: left-drag elsewhere orbits, right/middle-drag pans, the wheel zooms towards the cursor;
// keys: F fit, 1 / 3 / 7 front / right / top (Ctrl: back / left / bottom, as in Blender), Home reset.
//
// Speed on software OpenGL: a changed picture (camera, model, cut, size) is first drawn at a reduced
// resolution into an offscreen framebuffer and scaled up, then drawn again at full resolution
// refineDelayMs() after the last change, in horizontal bands of about 40 ms over successive frames (so
// the event loop, and a new drag, get through between bands). The reduction is chosen from the
// measured cost of past frames (1 = none on a fast GPU, up to 4) unless fixed with
// setReducedResolutionDivisor(). Discrete changes (toggles, keys, setCamera) draw full resolution at
// once. Handles and hover highlights are drawn over the cached picture without re-rendering the wood.
#include <QImage>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLWidget>
#include <QTimer>
#include <array>
#include <memory>

#include "cut_gizmo.hpp"
#include "geometry/cut_plane.hpp"
#include "orbit_camera.hpp"
#include "render/board_wood.hpp"
#include "render/wood_model.hpp"
#include "surface_image.hpp"

class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;
class QOpenGLTexture;
class QPainter;

namespace kerf {

class BoardWoodTextures;
class WoodProgram;
class PartMeshRenderer;
struct Mesh;

class Viewport3D : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
  Q_OBJECT

 public:
  enum class CutSide { Hide, Ghost };

  explicit Viewport3D(QWidget* parent = nullptr);
  ~Viewport3D() override;

  // The wood to show (null: an empty view). Uploads on the next frame; cheap enough per slider move.
  // A new block size re-frames the camera; the same size keeps the view.
  void setModel(std::shared_ptr<const WoodModel> model);
  const std::shared_ptr<const WoodModel>& model() const { return model_; }

  // Log mode: the wood of a board cut from a log instead of the model's (whose block must be the
  // board's); null goes back to the model's wood. Uploads on the next frame (only what changed).
  void setBoardWood(std::shared_ptr<const BoardWood> wood);
  const std::shared_ptr<const BoardWood>& boardWood() const { return boardWood_; }

  void setCutPlane(const CutPlaneSetting& setting);
  const CutPlaneSetting& cutPlane() const { return gizmo_.setting(); }
  void setCutEnabled(bool enabled);
  bool cutEnabled() const { return cutEnabled_; }
  void setCutSide(CutSide side);
  CutSide cutSide() const { return cutSide_; }
  void setCutHandlesVisible(bool visible);  // the rings and arrow (default on)

  // Photos of faces A..F (any size; null = that face shows the model), projected onto the faces with
  // Block::blockToImage's pixel mapping when shown.
  void setFacePhotos(const std::array<QImage, 6>& photos);
  void setShowPhotos(bool show);
  bool showPhotos() const { return showPhotos_; }

  // The faces' own appearance (the photo-true faces, issue 17; A..F, null where a face has none), laid on
  // the faces as the photos are while `forModel` is the view's model; otherwise (a preview, an edit not
  // yet re-made) the faces show the model's wood. The photos, when shown, win.
  void setFaceAppearance(std::shared_ptr<const WoodModel> forModel, const std::array<QImage, 6>& faces);
  // The cut surface's own appearance, likewise, while the view shows its model and cut plane.
  void setCutAppearance(const CutAppearance& cut);
  // Whether the last frame laid appearance pictures on the faces / on the cut.
  bool showsFaceAppearance() const;
  bool showsCutAppearance() const;

  // A part placed in the block (block mm; null: none). Uploads on the next frame.
  void setPart(std::shared_ptr<const Mesh> placedMesh);
  bool showsPart() const { return part_ != nullptr; }

  // The default three-quarter view (faces A, B, E), fitted. Until the user zooms or pans, the view
  // stays fitted when the widget is resized or a block of another size arrives.
  void resetCamera();
  void fitCamera();  // keeps the angles
  const OrbitCamera& camera() const { return camera_; }
  void setCamera(const OrbitCamera& camera);  // viewport size is the widget's

  const CutGizmo& gizmo() const { return gizmo_; }

  // Strength of the fibre highlight (1 = the default finished look, 0 = off).
  void setFiberHighlight(float strength);
  float fiberHighlight() const { return fiberHighlight_; }

  // Rendering speed. divisor 0 = automatic (default), 1 = always full resolution, 2..4 = fixed.
  void setReducedResolutionDivisor(int divisor);
  int reducedResolutionDivisor() const { return fixedDivisor_; }
  void setRefineDelayMs(int ms);
  // The next frame is drawn completely at full resolution (e.g. before grabbing a screenshot).
  void refineNow();
  int refineDelayMs() const { return refineTimer_.interval(); }
  // glFinish before stopping the frame clock, so frameRendered() is the true GPU time (costs a stall).
  void setFinishFrames(bool finish) { finishFrames_ = finish; }
  // What the last frame drew: the divisor of its wood picture (1 = full resolution) and whether it
  // re-rendered the wood (false: only the overlay over the cached picture).
  int lastFrameDivisor() const { return lastDivisor_; }
  bool lastFrameRenderedScene() const { return lastRenderedScene_; }
  bool fullyRefined() const { return lastDivisor_ == 1 && !interactive_; }
  QString rendererName() const { return rendererName_; }  // GL_RENDERER, once initialised
  bool ready() const { return glReady_; }                 // initialised and the shaders built

  QSize sizeHint() const override { return {800, 600}; }
  QSize minimumSizeHint() const override { return {160, 120}; }

 signals:
  void cutPlaneEdited(kerf::CutPlaneSetting setting, bool finished);
  // Every frame's time in paintGL (also frames that only redraw the handles over the cached picture;
  // see lastFrameRenderedScene()). Honest GPU time with setFinishFrames(true).
  void frameRendered(double milliseconds);

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  enum class DragMode { None, Orbit, Pan, Cut };

  // The wood picture must be redrawn: `interactive` changes (drags, wheel, slider streams) draw reduced
  // first and refine later; discrete ones (toggles, key presses) draw at full resolution at once.
  void sceneChanged(bool interactive);
  void refine();
  int chooseDivisor() const;
  void uploadGeometry();
  void uploadPhotos();
  void uploadAppearance();
  // Draws the wood picture into `target`, only rows [rowBegin, rowEnd) (OpenGL rows, bottom-up).
  void renderScene(QOpenGLFramebufferObject& target, int rowBegin, int rowEnd);
  void noteCost(double ms, double pixels);
  int chooseBandCount(QSize full) const;
  QOpenGLShaderProgram& sceneProgram();  // the board's wood in log mode, else the model's
  void drawBlock(bool ghost);
  void drawCap();
  void drawPart();
  void drawOverlay(QPainter& painter);
  void setHover(CutGizmo::Handle handle);
  void updateCursor();
  void releaseGl();

  std::shared_ptr<const WoodModel> model_;
  bool modelDirty_ = false;
  std::shared_ptr<const BoardWood> boardWood_;
  Block block_;

  OrbitCamera camera_;
  bool autoFrame_ = true;  // re-fit on resize until the user zooms or pans
  CutGizmo gizmo_;
  bool cutEnabled_ = false;
  CutSide cutSide_ = CutSide::Ghost;
  bool handlesVisible_ = true;
  float fiberHighlight_ = 1.0f;

  std::shared_ptr<const Mesh> part_;
  bool partDirty_ = false;
  std::unique_ptr<PartMeshRenderer> partRenderer_;

  std::array<QImage, 6> photos_;
  bool photosDirty_ = false;
  bool showPhotos_ = false;

  std::shared_ptr<const WoodModel> faceAppearanceModel_;
  std::array<QImage, 6> faceAppearance_;
  CutAppearance cutAppearance_;
  bool appearanceDirty_ = false;

  // Interaction.
  DragMode dragMode_ = DragMode::None;
  QPointF lastMouse_;
  Qt::MouseButton dragButton_ = Qt::NoButton;
  bool emittedDuringDrag_ = false;
  CutGizmo::Handle hover_ = CutGizmo::Handle::None;

  // Rendering.
  bool glReady_ = false;
  bool glFunctions_ = false;
  QString failure_;
  QString rendererName_;
  std::unique_ptr<WoodProgram> blockProgram_;
  std::unique_ptr<QOpenGLShaderProgram> backgroundProgram_;
  std::unique_ptr<WoodProgram> boardProgram_;  // built when a board is first shown
  std::unique_ptr<BoardWoodTextures> boardTextures_;
  unsigned growthTexture_ = 0;  // the WoodProgram's growth table (re-bound every frame)
  unsigned vertexArray_ = 0, vertexBuffer_ = 0, capArray_ = 0, capBuffer_ = 0, emptyArray_ = 0;
  std::array<std::unique_ptr<QOpenGLTexture>, 6> photoTextures_;
  std::array<std::unique_ptr<QOpenGLTexture>, 6> faceAppearanceTextures_;
  std::unique_ptr<QOpenGLTexture> cutAppearanceTexture_;
  // The wood picture: reduced (while interacting) and full resolution, the latter drawn in horizontal
  // bands over several frames when refining after an interaction, so input is handled between bands.
  std::unique_ptr<QOpenGLFramebufferObject> reducedFbo_, fullFbo_;
  bool reducedValid_ = false;
  int reducedDivisor_ = 2;
  int fullBandsDone_ = 0, fullBandCount_ = 1;
  bool interactive_ = false;  // a change is streaming: draw reduced until the refine timer fires
  int fixedDivisor_ = 0;
  double msPerMegapixel_ = -1.0;  // measured cost of the wood picture (negative: not yet known)
  QTimer refineTimer_;
  bool finishFrames_ = false;
  int lastDivisor_ = 1;
  bool lastRenderedScene_ = false;
};

}  // namespace kerf
