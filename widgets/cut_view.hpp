#pragma once
// The cut surface of the current cut plane at true scale, drawn live by the GLSL wood model
// (shaders/image_plane.frag): every widget pixel is mapped to the block point under it and evaluated
// on the GPU, so the picture is sharp at any zoom and matches core's renderCut pixel for pixel.
//
// Log mode (setBoardWood): the cut shows the wood of a board cut from a log, its knot model evaluated per
// pixel (shaders/board_wood.glsl), the same field as the board's faces.
//
// Orientation (docs/coordinates.md): the plane is seen from the side its normal points to, "up" on
// screen is CutPlane::up() and "right" is CutPlane::right(). Outside the cut polygon the view shows its
// background. A millimetre ruler runs along the bottom and left edges; it measures from the left and
// bottom edges of the rectangle bounding the cut (for a plane parallel to a face: the block's edges).
//
// True scale: a zoom of 1:1 shows 1 mm as 1 mm on the monitor, from QScreen::physicalDotsPerInch (the
// size the monitor reports through EDID); where that is implausible (outside 50..600 dpi) the logical
// DPI is used instead, and setScreenPixelsPerMm() overrides both (calibration). The view starts at 1:1.
//
// Mouse and keys: wheel zooms towards the cursor, +/- zoom about the centre, 1 = 1:1, F = fit, drag
// (left or middle button) pans.
//
// Speed: while the model or the plane changes quickly (a slider drag), or while panning and zooming,
// frames that would take longer than ~30 ms at full resolution are drawn at a reduced resolution and
// scaled up; ~150 ms after the last change one full-resolution frame refines the picture. Only the
// cut polygon is rasterised (shaders/cut_polygon.vert with image_plane.frag), since Mesa's llvmpipe
// pays for the whole wood model even on pixels that the shader's block test leaves empty.
// Measured on llvmpipe, 2 cores, 800 x 600 (tests/widgets/test_cut_view.cpp, frameTimes): the cut
// filling the view ~90-150 ms at full resolution, ~25-50 ms at 1/2, ~12-25 ms at 1/3; at 1:1 ~10-17 ms.
#include <QElapsedTimer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <QPainterPath>
#include <QPolygonF>
#include <QString>
#include <QTimer>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>

#include "field/ring_uncertainty.hpp"
#include "geometry/cut_plane.hpp"
#include "render/board_wood.hpp"
#include "render/wood_model.hpp"
#include "surface_image.hpp"

class QAction;

namespace kerf {

class BoardWoodTextures;
class WoodProgram;

// What the cut panel shows where a photo of the real cut is aligned on the plane (cut_view_compare.cpp):
// the model's cut, the photo, photo | model at a draggable line, or where they differ (the faces view's
// compare displays, drawn alike: compare_overlay.hpp).
enum class CutDisplay { Model, Photo, Split, Difference };
inline constexpr int kCutDisplayCount = 4;

// A photo of the real cut, rectified onto the cut of `plane` (its pixels' block points in photo.grid),
// and the difference heat map on the same grid (face_difference.hpp) with what it was computed against.
struct CutPhotoPicture {
  SurfaceImage photo;
  CutPlaneSetting plane;
  QImage difference;  // null until computed
  std::shared_ptr<const WoodModel> differenceModel;
  std::shared_ptr<const BoardWood> differenceBoard;  // log mode: the board's wood it was computed against
  bool differenceOfAppearance = false;               // against the photo-true cut, not the procedural wood
  qint64 differencePhoto = 0;  // the photo's QImage::cacheKey: a heat map of an earlier photo is never shown
};

class CutView : public QOpenGLWidget, protected QOpenGLExtraFunctions {
  Q_OBJECT

 public:
  explicit CutView(QWidget* parent = nullptr);
  ~CutView() override;

  void setModel(std::shared_ptr<const WoodModel> model);
  const std::shared_ptr<const WoodModel>& model() const { return model_; }
  // Log mode: the wood of a board cut from a log instead of the model's (whose block must be the
  // board's); null goes back to the model's wood.
  void setBoardWood(std::shared_ptr<const BoardWood> wood);
  const std::shared_ptr<const BoardWood>& boardWood() const { return boardWood_; }
  // How sure the fit is (field/ring_uncertainty.hpp) for the model's field, drawn over the cut while
  // showRingUncertaintyAction() is checked, and said for the point under the cursor; null: none.
  void setRingUncertainty(std::shared_ptr<const RingUncertainty> uncertainty);
  const std::shared_ptr<const RingUncertainty>& ringUncertainty() const { return ringUncertainty_; }
  bool showsRingUncertainty() const;
  void setCutPlane(const CutPlaneSetting& setting);
  const CutPlaneSetting& cutPlane() const { return setting_; }
  // The cut's own appearance (the photo-true cut, issue 17), drawn instead of the GLSL wood while the view
  // shows its model and plane (surface_image.hpp); until then, and after an edit, the model's wood.
  void setCutAppearance(const CutAppearance& cut);
  bool showsCutAppearance() const;
  // The cut photo (null photo.image: none) and how it is compared (cut_view_compare.cpp). It is shown only
  // on its own plane; on another the view says the photo is of another cut (cutPhotoStale()).
  void setCutPhoto(const CutPhotoPicture& picture);
  const CutPhotoPicture& cutPhoto() const { return cutPhoto_; }
  void setCutDisplay(CutDisplay display);
  CutDisplay cutDisplay() const { return cutDisplay_; }
  // Where the photo | model line crosses the cut's bounding rectangle, as a fraction of its width.
  void setCutSplitPosition(double fraction);
  double cutSplitPosition() const { return cutSplit_; }
  bool showsCutPhoto() const;       // a photo on the plane shown, and a display that shows it
  bool cutPhotoStale() const;       // a photo, but of another plane than the one shown
  bool differenceUpToDate() const;  // the heat map is of the model (and appearance) shown
  // The split line's widget x (the cut's bounding rectangle), when Split shows it.
  std::optional<qreal> cutSplitX() const;
  // The photo-true cut image while it is shown instead of the GLSL wood; null otherwise.
  QImage shownCutAppearance() const { return showsCutAppearance() ? appearance_.surface.image : QImage(); }
  // The plane, when it passes through the block of the current model.
  std::optional<CutPlane> plane() const;

  // Zoom, in widget (logical) pixels per millimetre of wood.
  double pixelsPerMm() const { return pixelsPerMm_; }
  void setZoom(double pixelsPerMm);               // about the view's centre
  void zoomBy(double factor, QPointF anchor);     // keeps the wood under `anchor` in place
  void zoomToFit();                               // the whole cut, with a margin for the rulers
  void zoomToActualSize();                        // 1:1, centred on the cut
  double screenPixelsPerMm() const;               // the zoom of 1:1
  void setScreenPixelsPerMm(double pixelsPerMm);  // calibration; 0 = from the screen (default)
  static constexpr double kMinPixelsPerMm = 0.2, kMaxPixelsPerMm = 400.0;

  // Where things are: plane coordinates (CutPlane mm, relative to the plane's point) under a widget
  // point, the block point there (nothing outside the cut), and back.
  glm::vec2 planePointAt(QPointF widgetPos) const;
  QPointF widgetPointOf(glm::vec2 planeMm) const;
  std::optional<glm::vec3> blockPointAt(QPointF widgetPos) const;
  // What cursorPositionChanged() says for a widget point ("" outside the cut).
  QString positionText(QPointF widgetPos) const;
  // The outline of the cut (the plane's intersection with the block) in widget coordinates.
  QPolygonF cutOutline() const;
  // The ruler bands, in widget coordinates.
  QRectF bottomRulerRect() const;
  QRectF leftRulerRect() const;
  QRectF scaleRect() const;  // the scale (1:1, 2:1, ...) at the right end of the bottom ruler
  static QColor rulerColor();
  static QColor backgroundColor();

  // Rendering resolution. renderScale() is the divisor of the last frame (1 = every device pixel was
  // evaluated, 2 = every second one in each direction, ...); lastFrameMs() its GPU time (glFinish).
  int renderScale() const { return lastScale_; }
  double lastFrameMs() const { return lastFrameMs_; }
  void setAdaptiveResolution(bool on);          // default on
  void setForcedRenderScale(int scale);         // 0 = adaptive; 1.. = always that (measurements)
  void setInteractiveFrameBudgetMs(double ms);  // default 30
  static constexpr int kRefineDelayMs = 150;
  // The clock (milliseconds, monotonic) that tells a stream of changes from single ones. Tests set a
  // clock they advance themselves, so what they check does not depend on how busy the machine is.
  // nullptr: the real (steady) clock, the default.
  using Clock = std::function<qint64()>;
  void setClock(Clock clock);

  // Actions with their shortcuts (1, F, +, -) for menus and toolbars; they act on this view.
  QAction* actualSizeAction() const { return actualSizeAction_; }
  QAction* fitAction() const { return fitAction_; }
  QAction* zoomInAction() const { return zoomInAction_; }
  QAction* zoomOutAction() const { return zoomOutAction_; }
  QAction* showRingUncertaintyAction() const { return showRingUncertaintyAction_; }  // U, checkable

  QSize sizeHint() const override { return {640, 480}; }
  QSize minimumSizeHint() const override { return {160, 120}; }

 signals:
  // The cursor's position on the plane (mm from the ruler origins) and in the block (mm); empty when
  // the cursor leaves the cut.
  void cursorPositionChanged(const QString& text);
  void zoomChanged(double pixelsPerMm);
  // After every frame: its GPU time and resolution divisor.
  void frameRendered(double milliseconds, int renderScale);
  void cutSplitPositionChanged(double fraction);  // also while the line is dragged
  // Log mode's wood was replaced (another board, log or knot edit; setBoardWood).
  void boardWoodChanged();
  // The GLSL program could not be built (the message is also drawn in the view).
  void glError(const QString& message);

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  enum class Framing { ActualSize, Fit, Free };  // what happens to the view when the cut changes
  void cleanupGL();
  void cutChanged();
  void reframe();
  void changedInteractively();  // a change that may come again soon: draw fast, refine later
  int chooseRenderScale() const;
  void drawWood(int scale);
  void drawOverlay();
  void drawRingUncertainty(class QPainter& painter, const QPolygonF& outline);
  void drawCutAppearance(class QPainter& painter) const;
  void drawSurface(class QPainter& painter, const SurfaceImage& surface, const QPainterPath& clip) const;
  void drawCutPhoto(class QPainter& painter) const;  // cut_view_compare.cpp
  QRectF cutRect() const;                            // the cut's bounding rectangle, widget pixels
  bool cutSplitPress(class QMouseEvent* event);
  bool cutSplitMove(class QMouseEvent* event);
  void drawRulers(class QPainter& painter) const;
  void setPixelsPerMm(double pixelsPerMm, QPointF anchor);
  void updateCursorText(QPointF widgetPos);
  std::optional<PlaneRect> bounds() const;

  std::shared_ptr<const WoodModel> model_;
  std::shared_ptr<const RingUncertainty> ringUncertainty_;
  std::shared_ptr<const BoardWood> boardWood_;
  CutAppearance appearance_;
  CutPhotoPicture cutPhoto_;
  CutDisplay cutDisplay_ = CutDisplay::Model;
  double cutSplit_ = 0.5;
  bool draggingSplit_ = false;
  CutPlaneSetting setting_;
  std::optional<CutPlane> plane_;

  Framing framing_ = Framing::ActualSize;
  double pixelsPerMm_ = 96.0 / 25.4;
  glm::vec2 center_{0.0f};  // plane mm shown at the widget's centre
  double screenPixelsPerMmOverride_ = 0.0;

  // Interaction
  bool panning_ = false;
  QPointF lastMouse_;
  QPointF cursor_{-1, -1};
  bool cursorInside_ = false;
  QString lastCursorText_;

  // GL state
  std::unique_ptr<WoodProgram> program_;
  std::unique_ptr<WoodProgram> boardProgram_;  // built when a board is first shown
  std::unique_ptr<BoardWoodTextures> boardTextures_;
  QString glError_;
  unsigned vertexArray_ = 0, vertexBuffer_ = 0;  // the cut polygon, the only geometry drawn
  unsigned smallFbo_ = 0, smallColor_ = 0;
  QSize smallSize_;
  std::shared_ptr<const WoodModel> uploadedModel_;  // the model whose uniforms the program holds
  unsigned growthTexture_ = 0;                      // its growth table (owned by program_)

  // Adaptive resolution
  bool adaptive_ = true;
  int forcedScale_ = 0;
  double budgetMs_ = 30.0;
  bool interactive_ = false;
  Clock clock_;
  std::optional<qint64> lastChangeMs_;
  QTimer refineTimer_;
  double msPerMegapixel_ = -1.0;  // measured cost of a full-resolution frame (smoothed)
  int lastScale_ = 1;
  double lastFrameMs_ = 0.0;

  QAction* actualSizeAction_ = nullptr;
  QAction* fitAction_ = nullptr;
  QAction* zoomInAction_ = nullptr;
  QAction* zoomOutAction_ = nullptr;
  QAction* showRingUncertaintyAction_ = nullptr;
};

}  // namespace kerf
