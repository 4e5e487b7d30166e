#pragma once
// The ring-tracing tools of the faces view: draws the annotations (ring traces, year numbers, knot
// marks) over a FacesView and turns mouse and keys into edits of them.
//
// It never changes annotations itself: every edit is announced with edited(after, undoText) and the
// owner (the editor's Document, one undo step per edit) hands the new value back with
// setAnnotations(). Traces are kept in face millimetres (core/rings/annotations.hpp), so they sit on
// the wood whatever is shown (photos or model) and at any zoom.
//
// Tools (actions with shortcuts while the faces view has focus):
//   Navigate, "Look" (H): the faces view's own navigation only.
//   Select (V): click a trace or knot mark, Shift+click adds/removes, drag a rectangle over traces.
//   Polyline, "Line" (P): click points along a ring; Enter or a double-click finishes, Backspace takes back
//   the
//     last point, Esc cancels.
//   Freehand, "Pencil" (D): drag along a ring; the stroke is smoothed and resampled when the button is
//   released. Knot (K): click where a knot meets a face, then where it leaves (usually another face): the two
//     marks form one knot, drawn connected. Esc ends a knot after one mark.
// Edits on the selection (any tool): Delete, S splits the trace under the cursor there, J joins the
// selected traces (one face) through their nearest ends, N numbers the selection by year, Shift+N
// shifts the selection's year numbers. Middle-drag, Space+drag and the wheel still navigate.
#include <QAction>
#include <QObject>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <optional>
#include <vector>

#include "rings/annotations.hpp"
#include "rings/knot_outline.hpp"

class QActionGroup;
class QInputDialog;
class QKeyEvent;
class QMouseEvent;
class QPainter;

namespace kerf {

class FacesView;

class AnnotationLayer : public QObject {
  Q_OBJECT

 public:
  enum class Tool { Navigate, Select, Polyline, Freehand, Knot };

  explicit AnnotationLayer(FacesView* view);

  void setAnnotations(const Annotations& annotations);  // keeps the selection where it still fits
  const Annotations& annotations() const { return annotations_; }

  // The knots' edges the last fit found on the photos (rings/knot_outline.hpp, issue 19 item 2), drawn
  // around their marks; an outline whose mark has moved since (or is gone) is not drawn.
  void setKnotOutlines(std::vector<KnotOutline> outlines);
  const std::vector<KnotOutline>& knotOutlines() const { return knotOutlines_; }
  // The outline found from mark `knot` (an index into annotations().knots) as it is now, if any.
  const KnotOutline* outlineOfMark(std::size_t knot) const;

  Tool tool() const { return tool_; }
  void setTool(Tool tool);

  // Tool actions (checkable, exclusive) and edit actions, with their shortcuts; add them to a tool bar
  // and to a widget that contains the faces view (their shortcuts work while focus is in it).
  QList<QAction*> toolActions() const;
  QList<QAction*> editActions() const;

  // Selection: indices into annotations().traces and annotations().knots.
  const std::vector<std::size_t>& selectedTraces() const { return selectedTraces_; }
  const std::vector<std::size_t>& selectedKnots() const { return selectedKnots_; }
  void setSelection(std::vector<std::size_t> traces, std::vector<std::size_t> knots = {});
  void clearSelection() { setSelection({}, {}); }
  std::optional<std::size_t> hoveredTrace() const { return hoveredTrace_; }

  // The edits behind the actions (also callable directly). Each emits edited() once, or message()
  // saying why nothing happened.
  void deleteSelection();
  void splitAt(QPointF widgetPos);  // the trace nearest to the point, there
  void joinSelection();
  void numberSelection(std::optional<int> year);
  void shiftSelectionYears(int offset);
  // Asks for a year / an offset (non-blocking dialogs) and applies it.
  void askYearForSelection();
  void askYearOffsetForSelection();
  // Knot marks (annotation_layer_knots.cpp): release the selected knots' marks, or hold them again when
  // all are released; set their accuracy (mm); ask for it (non-blocking dialog).
  void toggleReleaseOfSelectedKnots();
  // Ignore the knot's edge found around the selected marks (a wrong outline), or use it again when all are
  // ignored.
  void toggleIgnoredEdgeOfSelectedKnots();
  void setSelectedKnotAccuracy(float mm);
  void askKnotAccuracyForSelection();

  // Traces are drawn (and picked) only while visible and while the view's overlay is visible
  // (View > Show Ring Traces).
  void setVisible(bool visible);
  bool isVisible() const { return visible_; }

  // Where a face-mm point is drawn now, and the face point under a widget point.
  QPointF toWidget(FaceId face, glm::vec2 faceMm) const;
  struct FacePoint {
    FaceId face;
    glm::vec2 mm;
  };
  std::optional<FacePoint> toFace(QPointF widgetPos) const;

 signals:
  void edited(const kerf::Annotations& after, const QString& undoText);
  void toolChanged(kerf::AnnotationLayer::Tool tool);
  void selectionChanged();
  void message(const QString& text);  // for the status bar

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void createActions();
  void paint(QPainter& painter) const;
  void paintTrace(QPainter& painter, const RingTrace& trace, bool selected, bool hovered) const;
  void paintKnots(QPainter& painter) const;
  void paintKnotOutlines(QPainter& painter) const;
  void paintDraft(QPainter& painter) const;
  bool mousePress(QMouseEvent* event);
  bool mouseMove(QMouseEvent* event);
  bool mouseRelease(QMouseEvent* event);
  bool mouseDoubleClick(QMouseEvent* event);
  bool keyPress(QKeyEvent* event);
  void finishPolyline();
  void finishFreehand();
  void cancelDraft();
  void placeKnotMark(QPointF widgetPos);
  void startKnotDrag(std::size_t knot, QPointF widgetPos);
  void moveKnotDrag(QPointF widgetPos);
  void finishKnotDrag();
  bool cancelKnotDrag();  // false when no drag was under way
  QString knotMarkText(std::size_t knot) const;
  void createKnotActions();
  QAction* makeEditAction(const QString& text, const QKeySequence& key, const QString& tip);
  QInputDialog* openDialog(const char* objectName,
                           const QString& title) const;  // closed and deleted by itself
  void emitEdit(Annotations after, const QString& text, std::vector<std::size_t> selectTraces,
                std::vector<std::size_t> selectKnots = {});
  std::optional<std::size_t> traceAt(QPointF widgetPos, qreal tolerancePx) const;
  std::optional<std::size_t> knotAt(QPointF widgetPos, qreal tolerancePx) const;
  glm::vec2 clampToFace(FaceId face, QPointF widgetPos) const;
  double pxPerMm(FaceId face) const;
  void updateCursor();
  void updateActions();
  bool shown() const;

  FacesView* view_;
  Annotations annotations_;
  std::vector<KnotOutline> knotOutlines_;
  Tool tool_ = Tool::Select;
  bool visible_ = true;
  std::vector<std::size_t> selectedTraces_, selectedKnots_;
  std::optional<std::size_t> hoveredTrace_, hoveredKnot_;

  // Drawing under way.
  std::optional<FaceId> draftFace_;
  std::vector<glm::vec2> draft_;  // face mm
  bool stroking_ = false;         // freehand button held
  std::optional<QPointF> cursor_;
  std::optional<int> pendingKnot_;  // a knot with one mark so far
  // A knot mark being dragged (Select): which, where it was, where the press was, whether it moved.
  std::optional<std::size_t> draggedKnot_;
  glm::vec2 draggedKnotFrom_{0.0f};
  QPointF knotPress_;
  bool knotMoved_ = false;
  QAction* releaseKnotAction_ = nullptr;
  QAction* knotAccuracyAction_ = nullptr;
  QAction* knotEdgeAction_ = nullptr;
  struct FlagTexts {
    QString undo, status;
  };
  void toggleSelectedKnotFlag(bool KnotMark::*flag, const FlagTexts& on, const FlagTexts& off);
  // Rubber band.
  std::optional<QPointF> bandStart_;
  QRectF band_;
  bool spaceHeld_ = false;

  QActionGroup* toolGroup_ = nullptr;
  QAction* toolAction_[5] = {};
  QAction* deleteAction_ = nullptr;
  QAction* splitAction_ = nullptr;
  QAction* joinAction_ = nullptr;
  QAction* numberAction_ = nullptr;
  QAction* renumberAction_ = nullptr;
};

}  // namespace kerf
