#pragma once
// The six faces of a block laid out as the unfolded Mokume cross (B above A, D below, C left, E and F
// to the right; see kerf::crossSlot), each labelled with its letter, scaled to fit with the block's
// proportions kept. Faces are placed by their size in mm, so photos of any resolution line up, and
// edges that touch in the cross are the same edge of the block (docs/coordinates.md).
//
// Two sets of images: the photos and the model's renderings. The view shows the photos, the model,
// or both with the model blended over the photos at an opacity (FaceDisplay). A set that is empty
// stands in for the other, so a project without photos still shows its renderings.
//
// Compare displays (faces_view_compare.cpp): Split shows each face's photo left of a vertical line and
// the model right of it, the line at the same fraction of every face's width (splitPosition(); drag it
// with the left button; the ring-tracing tools step aside on the line). Difference shows
// where the model departs from the photo as a heat map (face_difference.hpp: black where they agree,
// orange where the model is lighter, blue where darker) with its legend in the bottom-right corner; the
// maps are computed off the GUI thread (face_difference_maps.hpp), the model shown dimmed until they
// come. Photo and model are registered by face position: both are stretched over the whole face, so a
// photo pixel meets the model at the same place on the wood whatever either's resolution. Faces without
// a photo show the model, labelled.
//
// Navigation: the wheel zooms towards the cursor along a ladder of factors (1 = fit); middle-drag or
// Space + left-drag pans; F or a double-click fits; +/- zoom about the centre.
// The cursor's face, pixel and block position (mm) are reported by cursorPositionChanged().
// Drag and drop: an image file (png, jpg, tif) dropped onto a face -> photoDropped(face, path); several
// images at once go to the faces their names start with ("A_col.png" -> A); a .kerf file or a folder
// -> documentDropped(path).
#include <QColor>
#include <QCursor>
#include <QImage>
#include <QPolygonF>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "geometry/block.hpp"

class QMouseEvent;
class QPainter;

namespace kerf {

enum class FaceDisplay { Photos, Model, Blend, Split, Difference };
inline constexpr int kFaceDisplayCount = 5;

class FacesView : public QWidget {
  Q_OBJECT

 public:
  explicit FacesView(QWidget* parent = nullptr);

  // The block whose faces are shown (their sizes in mm lay out the cross).
  void setBlock(const Block& block);
  const Block& block() const { return block_; }

  // The two sets, A..F; a null image leaves its face as an empty outline.
  void setPhotos(const std::array<QImage, 6>& photos);
  void setRenderings(const std::array<QImage, 6>& renderings);
  const std::array<QImage, 6>& photos() const { return photos_; }
  const std::array<QImage, 6>& renderings() const { return renderings_; }

  // Shows exactly `faces` (one set, nothing to blend): they become the photos, the renderings are
  // cleared. Kept for the editor shell, which swaps the set itself.
  void setFaces(const std::array<QImage, 6>& faces, const Block& block);
  void clear();  // both sets
  // The set drawn underneath: the photos (the model in Model display, or when there are no photos).
  const std::array<QImage, 6>& faces() const;
  bool hasFaces() const;

  void setDisplay(FaceDisplay display);
  FaceDisplay display() const { return display_; }
  // Opacity of the model over the photos in Blend display, 0 (photos only) .. 1 (model only).
  void setBlendOpacity(double opacity);
  double blendOpacity() const { return blendOpacity_; }
  // Where the line of Split display crosses each face, as a fraction of its width from the left edge:
  // 0 shows only the model, 1 only the photo.
  void setSplitPosition(double fraction);
  double splitPosition() const { return splitPosition_; }
  // Difference display: the heat maps A..F (null without a photo, or before the first are computed), and
  // whether they are of the photos and renderings shown now.
  const std::array<QImage, 6>& differenceMaps() const;
  bool differenceUpToDate() const;
  // Split display: whether a left press at a widget point takes the photo | model line, and whether it is
  // being dragged (the ring-tracing tools, which filter the view's mouse events, step aside for it).
  bool splitLineUnder(QPointF widgetPos) const { return splitLineAt(widgetPos).has_value(); }
  bool draggingSplit() const { return splitDrag_.has_value(); }

  // Polylines drawn over the faces (ring contours): per face A..F, in the pixel coordinates of an image
  // of imageSizes[face] pixels covering the whole face (continuous coordinates: a pixel's centre is at
  // (x + 0.5, y + 0.5)), so they line up with the photo whatever set is shown. Open polylines, drawn in
  // a bright colour while overlayVisible(), or each in its own colour (colors[face][i] for polyline i,
  // e.g. a fit's residual per contour) where colors are given.
  void setOverlayPolylines(const std::array<std::vector<QPolygonF>, 6>& polylines,
                           const std::array<QSize, 6>& imageSizes,
                           const std::array<std::vector<QColor>, 6>& colors = {});
  const std::array<std::vector<QColor>, 6>& overlayColors() const { return overlayColors_; }
  void clearOverlay();
  bool hasOverlay() const;
  void setOverlayVisible(bool visible);
  bool overlayVisible() const { return overlayVisible_; }

  // Drawn over the faces and their overlay, under the face letters, in widget coordinates (the annotation
  // tools of widgets/annotation_layer.hpp draw the ring traces and knot marks this way).
  void setForegroundPainter(std::function<void(QPainter&)> painter);

  // Shown centred while there are no faces ("Rendering faces…").
  void setPlaceholderText(const QString& text);

  // A title and a line of detail, drawn in the empty corner right of B ("Photos", "Ctrl+T: …").
  void setCaption(const QString& title, const QString& detail = {});

  // Where face `face` is drawn, in widget pixels, with the current zoom and pan.
  QRectF faceRect(FaceId face) const;

  // Zoom: 1 fits the cross into the view; steps follow zoomLadder().
  double zoom() const { return zoom_; }
  void setZoom(double zoom, std::optional<QPointF> anchor = std::nullopt);  // default anchor: the centre
  void zoomIn(std::optional<QPointF> anchor = std::nullopt);
  void zoomOut(std::optional<QPointF> anchor = std::nullopt);
  void fitToView();
  void panBy(QPointF deltaPx);
  QPointF pan() const { return pan_; }
  static const std::array<double, 16>& zoomLadder();

  // What is under a widget point: the face, and the text cursorPositionChanged() sends ("" outside faces).
  std::optional<FaceId> faceAt(QPointF widgetPos) const;
  QString positionText(QPointF widgetPos) const;
  // The block point (mm) under a widget point on a face.
  std::optional<glm::vec3> blockPointAt(QPointF widgetPos) const;

  QSize sizeHint() const override { return {960, 720}; }
  QSize minimumSizeHint() const override { return {240, 180}; }

 signals:
  void cursorPositionChanged(const QString& text);
  void photoDropped(kerf::FaceId face, const QString& path);
  void documentDropped(const QString& path);
  void zoomChanged(double zoom);
  void displayChanged(kerf::FaceDisplay display);
  void splitPositionChanged(double fraction);  // also while the line is dragged
  void differenceReady();                      // differenceMaps() are up to date

 protected:
  void paintEvent(QPaintEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void focusOutEvent(QFocusEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dragMoveEvent(QDragMoveEvent* event) override;
  void dragLeaveEvent(QDragLeaveEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  struct Layers {
    const std::array<QImage, 6>* base = nullptr;
    const std::array<QImage, 6>* overlay = nullptr;  // drawn at blendOpacity_ over base
  };
  Layers layers() const;
  QRectF fitRect(FaceId face) const;  // at zoom 1, no pan
  QRectF faceRect(FaceId face, double zoom, QPointF pan) const;
  static QPointF gapOffset(FaceId face);
  void drawFace(class QPainter& painter, const QRectF& target, const QImage& image) const;
  void drawLabel(QPainter& painter, const QRectF& rect, FaceId face, qreal side) const;
  void drawCaption(QPainter& painter) const;
  void drawOverlay(QPainter& painter, const QRectF& target, FaceId face) const;
  // Compare displays (faces_view_compare.cpp).
  bool comparing() const;  // Split or Difference, with photos and renderings
  void drawCompareFace(QPainter& painter, const QRectF& target, FaceId face) const;
  void drawSplitFace(QPainter& painter, const QRectF& target, const QImage& photo, const QImage& model) const;
  void drawDifferenceFace(QPainter& painter, const QRectF& target, FaceId face) const;
  void drawTag(QPainter& painter, const QRectF& face, const QString& text, Qt::Alignment corner) const;
  std::optional<FaceId> splitLineAt(QPointF widgetPos) const;  // a face whose split line is under it
  bool splitMousePress(QMouseEvent* event);
  bool splitMouseMove(QMouseEvent* event);
  bool splitMouseRelease(QMouseEvent* event);
  void requestDifferences();  // when Difference is shown and its inputs changed
  void updateCursorText(std::optional<QPointF> widgetPos);
  bool acceptDrag(class QDropEvent* event);  // sets dropFace_; true when the drop would do something

  std::array<QImage, 6> photos_, renderings_;
  std::array<std::vector<QPolygonF>, 6> overlay_;
  std::array<QSize, 6> overlaySizes_;
  std::array<std::vector<QColor>, 6> overlayColors_;
  bool overlayVisible_ = true;
  std::function<void(QPainter&)> foreground_;
  Block block_;
  FaceDisplay display_ = FaceDisplay::Photos;
  double blendOpacity_ = 0.5;
  double splitPosition_ = 0.5;
  std::optional<FaceId> splitDrag_;           // the face whose split line is being dragged
  std::optional<QCursor> cursorBeforeSplit_;  // while the cursor shows the split line can be dragged
  class FaceDifferenceMaps* differences_ = nullptr;
  bool differencesStale_ = true;  // photos or renderings changed since the last request
  QString placeholder_;
  QString captionTitle_, captionDetail_;

  double zoom_ = 1.0;
  QPointF pan_;  // widget pixels
  double wheelAccumulator_ = 0;
  bool spaceHeld_ = false;
  bool panning_ = false;
  QPointF lastMouse_;
  QString lastCursorText_;
  std::optional<FaceId> dropFace_;  // highlighted while an image is dragged over a face
};

}  // namespace kerf
