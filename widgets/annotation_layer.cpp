#include "annotation_layer.hpp"

#include <QActionGroup>
#include <QInputDialog>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QtMath>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "faces_view.hpp"

namespace kerf {

namespace {

const QColor kDetectedColor(255, 40, 200);  // as the detector's contours were always drawn
const QColor kDrawnColor(40, 225, 255);
const QColor kDraftColor(255, 225, 0);
const QColor kKnotColor(255, 140, 20);
const QColor kHalo(0, 0, 0, 160);

constexpr qreal kPickPx = 7;      // how near the cursor must be to a trace to pick it
constexpr qreal kKnotPickPx = 9;  // to a knot mark
constexpr qreal kSplitPx = 14;    // S splits the trace within this distance of the cursor

qreal distanceToSegment(QPointF p, QPointF a, QPointF b) {
  const QPointF d = b - a;
  const qreal len2 = QPointF::dotProduct(d, d);
  const qreal t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
  const QPointF q = a + t * d;
  return std::hypot(p.x() - q.x(), p.y() - q.y());
}

QPen pen(const QColor& color, qreal width, Qt::PenStyle style = Qt::SolidLine) {
  QPen p(color, width, style, Qt::RoundCap, Qt::RoundJoin);
  p.setCosmetic(true);
  return p;
}

}  // namespace

AnnotationLayer::AnnotationLayer(FacesView* view) : QObject(view), view_(view) {
  createActions();
  view_->installEventFilter(this);
  view_->setForegroundPainter([this](QPainter& painter) { paint(painter); });
  updateActions();
}

// --- Actions -------------------------------------------------------------------------------------

void AnnotationLayer::createActions() {
  toolGroup_ = new QActionGroup(this);
  struct ToolSpec {
    Tool tool;
    QString text;
    Qt::Key key;
    QString tip;
  };
  const ToolSpec tools[] = {
      {Tool::Navigate, tr("Look"), Qt::Key_H,
       tr("Look around the faces without changing anything: the wheel zooms, middle-drag or Space+drag pans, "
          "F fits (H)")},
      {Tool::Select, tr("Select"), Qt::Key_V,
       tr("Pick ring traces and knot marks to delete, split, join or number: click one, Shift+click to add "
          "more, or drag a box around them (V)")},
      {Tool::Polyline, tr("Line"), Qt::Key_P,
       tr("Trace a ring by clicking points along the latewood edge; Enter or a double-click finishes, "
          "Backspace takes back the last point, Esc cancels (P)")},
      {Tool::Freehand, tr("Pencil"), Qt::Key_D,
       tr("Trace a ring by dragging along it like a pencil; the stroke is smoothed when you let go (D)")},
      {Tool::Knot, tr("Knot"), Qt::Key_K,
       tr("Mark a knot: click its centre where it comes out on one face, then where it comes out on the "
          "other; the two marks are drawn joined (K)")},
  };
  for (const ToolSpec& spec : tools) {
    auto* action = new QAction(spec.text, this);
    action->setCheckable(true);
    action->setShortcut(QKeySequence(spec.key));
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    action->setToolTip(spec.tip);
    action->setData(static_cast<int>(spec.tool));
    toolGroup_->addAction(action);
    view_->addAction(action);
    const Tool tool = spec.tool;
    connect(action, &QAction::triggered, this, [this, tool] { setTool(tool); });
    toolAction_[static_cast<int>(spec.tool)] = action;
  }
  toolAction_[static_cast<int>(tool_)]->setChecked(true);

  const auto make = [this](const QString& text, const QKeySequence& key, const QString& tip) {
    return makeEditAction(text, key, tip);
  };
  deleteAction_ = make(tr("Delete"), QKeySequence(Qt::Key_Delete),
                       tr("Delete the selected ring traces and knot marks (Del)"));
  splitAction_ = make(tr("Split"), QKeySequence(Qt::Key_S),
                      tr("Cut the ring trace under the cursor in two at that point, e.g. where it jumps to "
                         "the next ring (S)"));
  joinAction_ = make(tr("Join"), QKeySequence(Qt::Key_J),
                     tr("Join the selected pieces of one ring on one face into a single trace, through their "
                        "nearest ends (J)"));
  numberAction_ = make(tr("Year"), QKeySequence(Qt::Key_N),
                       tr("Number the selected traces by year: count the rings outwards from the pith; the "
                          "numbers only need to be right relative to each other (N)"));
  renumberAction_ = make(tr("±Years"), QKeySequence(Qt::SHIFT | Qt::Key_N),
                         tr("Add or take years from the numbers of all selected traces at once, e.g. after "
                            "finding a missed ring (Shift+N)"));
  connect(deleteAction_, &QAction::triggered, this, &AnnotationLayer::deleteSelection);
  connect(splitAction_, &QAction::triggered, this, [this] {
    if (cursor_)
      splitAt(*cursor_);
    else
      emit message(tr("Point at the ring trace where it should be split, then press S."));
  });
  connect(joinAction_, &QAction::triggered, this, &AnnotationLayer::joinSelection);
  connect(numberAction_, &QAction::triggered, this, &AnnotationLayer::askYearForSelection);
  connect(renumberAction_, &QAction::triggered, this, &AnnotationLayer::askYearOffsetForSelection);
  createKnotActions();
}

QAction* AnnotationLayer::makeEditAction(const QString& text, const QKeySequence& key, const QString& tip) {
  auto* action = new QAction(text, this);
  action->setShortcut(key);
  action->setShortcutContext(Qt::WidgetWithChildrenShortcut);  // while the faces view has the focus
  action->setToolTip(tip);
  view_->addAction(action);
  return action;
}

QList<QAction*> AnnotationLayer::toolActions() const {
  return toolGroup_->actions();
}

QList<QAction*> AnnotationLayer::editActions() const {
  return {deleteAction_,   splitAction_,       joinAction_,         numberAction_,
          renumberAction_, releaseKnotAction_, knotAccuracyAction_, knotEdgeAction_};
}

void AnnotationLayer::updateActions() {
  const bool any = !selectedTraces_.empty() || !selectedKnots_.empty();
  deleteAction_->setEnabled(any);
  joinAction_->setEnabled(selectedTraces_.size() >= 2);
  numberAction_->setEnabled(!selectedTraces_.empty());
  renumberAction_->setEnabled(!selectedTraces_.empty());
  splitAction_->setEnabled(!annotations_.traces.empty());
  releaseKnotAction_->setEnabled(!selectedKnots_.empty());
  knotAccuracyAction_->setEnabled(!selectedKnots_.empty());
  knotEdgeAction_->setEnabled(!selectedKnots_.empty());
}

// --- State ---------------------------------------------------------------------------------------

void AnnotationLayer::setAnnotations(const Annotations& annotations) {
  annotations_ = annotations;
  std::erase_if(selectedTraces_, [&](std::size_t i) { return i >= annotations_.traces.size(); });
  std::erase_if(selectedKnots_, [&](std::size_t i) { return i >= annotations_.knots.size(); });
  if (hoveredTrace_ && *hoveredTrace_ >= annotations_.traces.size()) hoveredTrace_.reset();
  if (hoveredKnot_ && *hoveredKnot_ >= annotations_.knots.size()) hoveredKnot_.reset();
  updateActions();
  emit selectionChanged();
  view_->update();
}

void AnnotationLayer::setTool(Tool tool) {
  if (tool != tool_) {
    cancelDraft();
    pendingKnot_.reset();
    tool_ = tool;
    emit toolChanged(tool);
  }
  toolAction_[static_cast<int>(tool)]->setChecked(true);
  updateCursor();
  static const char* hints[] = {
      "Navigate: wheel zooms, middle-drag pans",
      "Select: click a trace or knot mark, Shift+click adds, drag a box; Del, S, J, N act on the selection",
      "Polyline: click points along a ring; Enter or double-click finishes, Backspace takes one back, Esc "
      "cancels",
      "Freehand: drag along a ring; the stroke is smoothed when you let go",
      "Knot: click where the knot comes out on one face, then on the other"};
  emit message(tr(hints[static_cast<int>(tool)]));
  view_->update();
}

void AnnotationLayer::setSelection(std::vector<std::size_t> traces, std::vector<std::size_t> knots) {
  std::erase_if(traces, [&](std::size_t i) { return i >= annotations_.traces.size(); });
  std::erase_if(knots, [&](std::size_t i) { return i >= annotations_.knots.size(); });
  selectedTraces_ = std::move(traces);
  selectedKnots_ = std::move(knots);
  updateActions();
  emit selectionChanged();
  view_->update();
}

void AnnotationLayer::setVisible(bool visible) {
  visible_ = visible;
  view_->update();
}

bool AnnotationLayer::shown() const {
  return visible_ && view_->overlayVisible();
}

void AnnotationLayer::updateCursor() {
  switch (tool_) {
    case Tool::Polyline:
    case Tool::Freehand:
    case Tool::Knot:
      view_->setCursor(Qt::CrossCursor);
      break;
    default:
      view_->unsetCursor();
  }
}

// --- Coordinates ---------------------------------------------------------------------------------

QPointF AnnotationLayer::toWidget(FaceId face, glm::vec2 mm) const {
  const QRectF r = view_->faceRect(face);
  const glm::vec2 size = faceSizeMm(view_->block(), face);
  return {r.left() + mm.x / size.x * r.width(), r.top() + mm.y / size.y * r.height()};
}

std::optional<AnnotationLayer::FacePoint> AnnotationLayer::toFace(QPointF pos) const {
  const auto face = view_->faceAt(pos);
  if (!face) return std::nullopt;
  return FacePoint{*face, clampToFace(*face, pos)};
}

glm::vec2 AnnotationLayer::clampToFace(FaceId face, QPointF pos) const {
  const QRectF r = view_->faceRect(face);
  const glm::vec2 size = faceSizeMm(view_->block(), face);
  const double u = std::clamp((pos.x() - r.left()) / r.width(), 0.0, 1.0);
  const double v = std::clamp((pos.y() - r.top()) / r.height(), 0.0, 1.0);
  return {static_cast<float>(u * size.x), static_cast<float>(v * size.y)};
}

double AnnotationLayer::pxPerMm(FaceId face) const {
  return view_->faceRect(face).width() / faceSizeMm(view_->block(), face).x;
}

std::optional<std::size_t> AnnotationLayer::traceAt(QPointF pos, qreal tolerance) const {
  if (!shown()) return std::nullopt;
  std::optional<std::size_t> best;
  qreal bestDistance = tolerance;
  for (std::size_t i = 0; i < annotations_.traces.size(); ++i) {
    const RingTrace& trace = annotations_.traces[i];
    if (!view_->faceRect(trace.face).adjusted(-tolerance, -tolerance, tolerance, tolerance).contains(pos))
      continue;
    for (std::size_t k = 0; k + 1 < trace.points.size(); ++k) {
      const qreal d = distanceToSegment(pos, toWidget(trace.face, trace.points[k]),
                                        toWidget(trace.face, trace.points[k + 1]));
      if (d <= bestDistance) bestDistance = d, best = i;
    }
  }
  return best;
}

std::optional<std::size_t> AnnotationLayer::knotAt(QPointF pos, qreal tolerance) const {
  if (!shown()) return std::nullopt;
  std::optional<std::size_t> best;
  qreal bestDistance = tolerance;
  for (std::size_t i = 0; i < annotations_.knots.size(); ++i) {
    const QPointF p = toWidget(annotations_.knots[i].face, annotations_.knots[i].point);
    const qreal d = std::hypot(p.x() - pos.x(), p.y() - pos.y());
    if (d <= bestDistance) bestDistance = d, best = i;
  }
  return best;
}

// --- Edits ---------------------------------------------------------------------------------------

void AnnotationLayer::emitEdit(Annotations after, const QString& text, std::vector<std::size_t> selectTraces,
                               std::vector<std::size_t> selectKnots) {
  emit edited(after, text);  // the owner applies it (setAnnotations) before this returns
  setSelection(std::move(selectTraces), std::move(selectKnots));
}

void AnnotationLayer::deleteSelection() {
  if (selectedTraces_.empty() && selectedKnots_.empty()) {
    emit message(tr("Nothing selected to delete: pick traces or knot marks with Select (V) first."));
    return;
  }
  Annotations after = removeTraces(annotations_, selectedTraces_);
  std::vector<std::size_t> knots = selectedKnots_;
  std::sort(knots.rbegin(), knots.rend());
  for (std::size_t k : knots) after.knots.erase(after.knots.begin() + static_cast<std::ptrdiff_t>(k));
  QStringList what;
  if (!selectedTraces_.empty()) what << tr("%n ring trace(s)", "", static_cast<int>(selectedTraces_.size()));
  if (!selectedKnots_.empty()) what << tr("%n knot mark(s)", "", static_cast<int>(selectedKnots_.size()));
  emitEdit(std::move(after), tr("Delete %1").arg(what.join(tr(" and "))), {});
}

void AnnotationLayer::splitAt(QPointF pos) {
  const auto index = traceAt(pos, kSplitPx);
  if (!index) {
    emit message(tr("There is no ring trace under the cursor to split."));
    return;
  }
  const RingTrace& trace = annotations_.traces[*index];
  const QRectF r = view_->faceRect(trace.face);
  const glm::vec2 size = faceSizeMm(view_->block(), trace.face);
  const glm::vec2 at(static_cast<float>((pos.x() - r.left()) / r.width() * size.x),
                     static_cast<float>((pos.y() - r.top()) / r.height() * size.y));
  Annotations after = splitTraceAt(annotations_, *index, at);
  if (after == annotations_) {
    emit message(tr("That is the end of the trace: there is nothing to split off."));
    return;
  }
  const std::size_t second = after.traces.size() - 1;
  emitEdit(std::move(after), tr("Split ring trace"), {*index, second});
}

void AnnotationLayer::joinSelection() {
  if (selectedTraces_.size() < 2) {
    emit message(tr("Select two or more traces of one face to join (Shift+click adds to the selection)."));
    return;
  }
  const FaceId face = annotations_.traces[selectedTraces_.front()].face;
  for (std::size_t i : selectedTraces_)
    if (annotations_.traces[i].face != face) {
      emit message(tr("Only traces on the same face can be joined."));
      return;
    }
  Annotations after = joinTracesAt(annotations_, selectedTraces_);
  const std::size_t first = selectedTraces_.front();
  const std::size_t removedBefore = static_cast<std::size_t>(std::count_if(
      selectedTraces_.begin() + 1, selectedTraces_.end(), [&](std::size_t i) { return i < first; }));
  emitEdit(std::move(after), tr("Join %n ring traces", "", static_cast<int>(selectedTraces_.size())),
           {first - removedBefore});
}

void AnnotationLayer::numberSelection(std::optional<int> year) {
  if (selectedTraces_.empty()) {
    emit message(tr("Select the traces to number first."));
    return;
  }
  const std::vector<std::size_t> keep = selectedTraces_;
  const int n = static_cast<int>(keep.size());
  emitEdit(setYears(annotations_, keep, year),
           year ? tr("Number %n trace(s) as year %1", "", n).arg(*year) : tr("Remove year numbers"), keep,
           selectedKnots_);
}

void AnnotationLayer::shiftSelectionYears(int offset) {
  const std::vector<std::size_t> keep = selectedTraces_;
  const bool numbered = std::any_of(keep.begin(), keep.end(),
                                    [&](std::size_t i) { return annotations_.traces[i].year.has_value(); });
  if (!numbered || offset == 0) {
    emit message(numbered ? tr("An offset of 0 changes nothing.")
                          : tr("None of the selected traces has a year number yet: number them with N."));
    return;
  }
  emitEdit(offsetYears(annotations_, keep, offset),
           tr("Renumber %n trace(s) by %1 years", "", static_cast<int>(keep.size()))
               .arg(offset > 0 ? QStringLiteral("+%1").arg(offset) : QString::number(offset)),
           keep, selectedKnots_);
}

QInputDialog* AnnotationLayer::openDialog(const char* objectName, const QString& title) const {
  auto* dialog = new QInputDialog(view_);  // non-blocking: tests and the user answer it later
  dialog->setObjectName(objectName);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setWindowTitle(title);
  return dialog;
}

void AnnotationLayer::askYearForSelection() {
  if (selectedTraces_.empty()) {
    emit message(tr("Select the traces to number first."));
    return;
  }
  int suggestion = 0;
  for (const RingTrace& t : annotations_.traces)
    if (t.year) suggestion = std::max(suggestion, *t.year + 1);
  if (const auto& first = annotations_.traces[selectedTraces_.front()]; first.year) suggestion = *first.year;
  QInputDialog* dialog = openDialog("annotationYearDialog", tr("Year Number"));
  dialog->setInputMode(QInputDialog::IntInput);
  dialog->setIntRange(0, 254);
  dialog->setIntValue(std::min(suggestion, 254));
  dialog->setLabelText(
      tr("Year of the selected ring(s), counted outwards from the pith.\nRelative numbers are "
         "enough: the ring nearest the pith gets the smallest (0-254)."));
  connect(dialog, &QInputDialog::intValueSelected, this, [this](int year) { numberSelection(year); });
  dialog->open();
}

void AnnotationLayer::askYearOffsetForSelection() {
  if (selectedTraces_.empty()) {
    emit message(tr("Select the numbered traces to renumber first."));
    return;
  }
  QInputDialog* dialog = openDialog("annotationYearOffsetDialog", tr("Shift Year Numbers"));
  dialog->setInputMode(QInputDialog::IntInput);
  dialog->setIntRange(-254, 254);
  dialog->setIntValue(1);
  dialog->setLabelText(
      tr("Years to add to the numbers of the selected traces\n(negative to take away; e.g. "
         "+1 when a ring nearer the pith was missed):"));
  connect(dialog, &QInputDialog::intValueSelected, this, [this](int offset) { shiftSelectionYears(offset); });
  dialog->open();
}

// --- Drawing tools ---------------------------------------------------------------------------------

void AnnotationLayer::cancelDraft() {
  draft_.clear();
  draftFace_.reset();
  stroking_ = false;
  view_->update();
}

void AnnotationLayer::finishPolyline() {
  if (!draftFace_ || draft_.size() < 2 || polylineLength(draft_) < 0.05f) {
    emit message(tr("A ring trace needs at least two points: keep clicking along the ring."));
    return;
  }
  Annotations after = annotations_;
  after.traces.push_back({*draftFace_, draft_, std::nullopt, TraceOrigin::Drawn});
  cancelDraft();
  const std::size_t index = after.traces.size() - 1;
  emitEdit(std::move(after), tr("Draw ring trace"), {index});
}

void AnnotationLayer::finishFreehand() {
  stroking_ = false;
  if (!draftFace_ || draft_.size() < 2 || polylineLength(draft_) < 0.2f) {
    cancelDraft();
    return;
  }
  // Smooth over a few screen pixels (hand jitter) but at least 0.4 mm of wood.
  const double px = pxPerMm(*draftFace_);
  const float sigma = std::max(0.4f, static_cast<float>(4.0 / px));
  const float spacing = std::max(0.1f, static_cast<float>(1.5 / px));
  std::vector<glm::vec2> smooth = smoothPolyline(draft_, spacing, sigma);
  smooth = simplifyPolyline(smooth, 0.02f);
  Annotations after = annotations_;
  after.traces.push_back({*draftFace_, std::move(smooth), std::nullopt, TraceOrigin::Drawn});
  cancelDraft();
  const std::size_t index = after.traces.size() - 1;
  emitEdit(std::move(after), tr("Draw ring trace (freehand)"), {index});
}

void AnnotationLayer::placeKnotMark(QPointF pos) {
  const auto at = toFace(pos);
  if (!at) {
    emit message(tr("Click on a face to mark the knot."));
    return;
  }
  Annotations after = annotations_;
  const bool second = pendingKnot_.has_value();
  const int id = second ? *pendingKnot_ : annotations_.nextKnotId();
  after.knots.push_back({id, at->face, at->mm});
  pendingKnot_ = second ? std::nullopt : std::optional<int>(id);
  const std::size_t index = after.knots.size() - 1;
  emitEdit(std::move(after),
           second ? tr("Mark knot %1 (where it leaves)").arg(id + 1) : tr("Mark knot %1").arg(id + 1), {},
           {index});
  emit message(
      second ? tr("Knot %1 marked on both faces.").arg(id + 1)
             : tr("Now click where knot %1 comes out on the other face (Esc: it shows on one face only).")
                   .arg(id + 1));
}

// --- Events --------------------------------------------------------------------------------------

bool AnnotationLayer::eventFilter(QObject* watched, QEvent* event) {
  if (watched != view_) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress:
      return mousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove:
      return mouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
      return mouseRelease(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonDblClick:
      return mouseDoubleClick(static_cast<QMouseEvent*>(event));
    case QEvent::KeyPress:
      return keyPress(static_cast<QKeyEvent*>(event));
    case QEvent::KeyRelease:
      if (static_cast<QKeyEvent*>(event)->key() == Qt::Key_Space &&
          !static_cast<QKeyEvent*>(event)->isAutoRepeat()) {
        spaceHeld_ = false;
        QMetaObject::invokeMethod(
            this, [this] { updateCursor(); }, Qt::QueuedConnection);
      }
      return false;
    case QEvent::FocusOut:
      spaceHeld_ = false;
      return false;
    case QEvent::Leave:
      cursor_.reset();
      if (hoveredTrace_ || hoveredKnot_) {
        hoveredTrace_.reset();
        hoveredKnot_.reset();
      }
      view_->update();
      return false;
    default:
      return false;
  }
}

bool AnnotationLayer::mousePress(QMouseEvent* event) {
  const QPointF pos = event->position();
  if (tool_ == Tool::Navigate || spaceHeld_) return false;
  // The faces view's photo | model line (Split display) is taken before a new trace or selection starts.
  const bool drafting = !draft_.empty() || pendingKnot_.has_value();
  if (event->button() == Qt::LeftButton && !drafting && view_->splitLineUnder(pos)) return false;
  if (event->button() == Qt::RightButton && tool_ == Tool::Polyline && !draft_.empty()) {
    finishPolyline();
    return true;
  }
  if (event->button() != Qt::LeftButton) return false;
  view_->setFocus(Qt::MouseFocusReason);
  const bool shift = event->modifiers() & Qt::ShiftModifier;
  switch (tool_) {
    case Tool::Select: {
      std::vector<std::size_t> traces = shift ? selectedTraces_ : std::vector<std::size_t>{};
      std::vector<std::size_t> knots = shift ? selectedKnots_ : std::vector<std::size_t>{};
      const auto toggle = [](std::vector<std::size_t>& set, std::size_t i) {
        const auto it = std::find(set.begin(), set.end(), i);
        if (it == set.end())
          set.push_back(i);
        else
          set.erase(it);
      };
      if (const auto knot = knotAt(pos, kKnotPickPx)) {
        // A knot is picked as a whole: both its marks.
        const int id = annotations_.knots[*knot].knot;
        for (std::size_t k = 0; k < annotations_.knots.size(); ++k)
          if (annotations_.knots[k].knot == id) toggle(knots, k);
        if (!shift) startKnotDrag(*knot, pos);
      } else if (const auto trace = traceAt(pos, kPickPx)) {
        toggle(traces, *trace);
      } else {
        bandStart_ = pos;
        band_ = QRectF(pos, pos);
      }
      setSelection(std::move(traces), std::move(knots));
      return true;
    }
    case Tool::Polyline: {
      if (draft_.empty()) {
        const auto at = toFace(pos);
        if (!at) {
          emit message(tr("Start the trace on a face."));
          return true;
        }
        draftFace_ = at->face;
        draft_.push_back(at->mm);
      } else {
        const glm::vec2 p = clampToFace(*draftFace_, pos);
        if (glm::length(p - draft_.back()) > 1e-4f) draft_.push_back(p);
      }
      view_->update();
      return true;
    }
    case Tool::Freehand: {
      const auto at = toFace(pos);
      if (!at) return true;
      draftFace_ = at->face;
      draft_ = {at->mm};
      stroking_ = true;
      return true;
    }
    case Tool::Knot:
      placeKnotMark(pos);
      return true;
    case Tool::Navigate:
      break;
  }
  return false;
}

bool AnnotationLayer::mouseMove(QMouseEvent* event) {
  const QPointF pos = event->position();
  cursor_ = pos;
  if (draggedKnot_ && (event->buttons() & Qt::LeftButton)) {
    moveKnotDrag(pos);
    return true;
  }
  if (stroking_ && draftFace_) {
    const glm::vec2 p = clampToFace(*draftFace_, pos);
    if (glm::length(p - draft_.back()) * pxPerMm(*draftFace_) >= 1.5) draft_.push_back(p);
  }
  if (bandStart_) band_ = QRectF(*bandStart_, pos).normalized();
  const auto hoverTrace = tool_ == Tool::Navigate ? std::nullopt : traceAt(pos, kPickPx);
  const auto hoverKnot = tool_ == Tool::Navigate ? std::nullopt : knotAt(pos, kKnotPickPx);
  if (hoverTrace != hoveredTrace_ || hoverKnot != hoveredKnot_) {
    hoveredTrace_ = hoverTrace;
    hoveredKnot_ = hoverKnot;
    if (hoveredKnot_) emit message(knotMarkText(*hoveredKnot_));
    if (hoveredTrace_) {
      const RingTrace& t = annotations_.traces[*hoveredTrace_];
      emit message(tr("Ring trace on face %1%2%3, %4 mm long")
                       .arg(QChar(faceLetter(t.face)))
                       .arg(t.year ? tr(", year %1").arg(*t.year) : QString())
                       .arg(t.origin == TraceOrigin::Detected ? tr(" (detected)") : QString())
                       .arg(polylineLength(t.points), 0, 'f', 1));
    }
  }
  view_->update();
  return false;  // the view still reports the cursor position and pans
}

bool AnnotationLayer::mouseRelease(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || view_->draggingSplit()) return false;
  if (draggedKnot_) {
    finishKnotDrag();
    return true;
  }
  if (stroking_) {
    finishFreehand();
    return true;
  }
  if (bandStart_) {
    const QRectF band = band_;
    bandStart_.reset();
    band_ = {};
    if (band.width() > 3 || band.height() > 3) {
      std::vector<std::size_t> traces = selectedTraces_;
      for (std::size_t i = 0; i < annotations_.traces.size(); ++i) {
        const RingTrace& t = annotations_.traces[i];
        const bool inside = std::any_of(t.points.begin(), t.points.end(),
                                        [&](glm::vec2 p) { return band.contains(toWidget(t.face, p)); });
        if (inside && std::find(traces.begin(), traces.end(), i) == traces.end()) traces.push_back(i);
      }
      std::vector<std::size_t> knots = selectedKnots_;
      for (std::size_t k = 0; k < annotations_.knots.size(); ++k)
        if (band.contains(toWidget(annotations_.knots[k].face, annotations_.knots[k].point)) &&
            std::find(knots.begin(), knots.end(), k) == knots.end())
          knots.push_back(k);
      setSelection(std::move(traces), std::move(knots));
    }
    view_->update();
    return true;
  }
  return tool_ != Tool::Navigate && !spaceHeld_;
}

bool AnnotationLayer::mouseDoubleClick(QMouseEvent* event) {
  if (tool_ == Tool::Polyline && event->button() == Qt::LeftButton) {
    if (!draft_.empty()) finishPolyline();
    return true;
  }
  // Drawing tools keep double-clicks for themselves; Select and Navigate fit the view as before.
  return tool_ == Tool::Freehand || tool_ == Tool::Knot;
}

bool AnnotationLayer::keyPress(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Space:
      if (!event->isAutoRepeat()) spaceHeld_ = true;
      return false;
    case Qt::Key_Return:
    case Qt::Key_Enter:
      if (tool_ == Tool::Polyline && !draft_.empty()) {
        finishPolyline();
        return true;
      }
      return false;
    case Qt::Key_Backspace:
      if (tool_ == Tool::Polyline && !draft_.empty()) {
        draft_.pop_back();
        if (draft_.empty()) draftFace_.reset();
        view_->update();
        return true;
      }
      return false;
    case Qt::Key_Escape:
      if (cancelKnotDrag()) return true;
      if (!draft_.empty()) {
        cancelDraft();
        emit message(tr("Trace cancelled."));
        return true;
      }
      if (pendingKnot_) {
        pendingKnot_.reset();
        emit message(tr("Knot marked on one face only."));
        return true;
      }
      if (!selectedTraces_.empty() || !selectedKnots_.empty()) {
        clearSelection();
        return true;
      }
      return false;
    default:
      return false;
  }
}

// --- Painting ------------------------------------------------------------------------------------

void AnnotationLayer::paint(QPainter& painter) const {
  painter.setRenderHint(QPainter::Antialiasing);
  if (shown()) {
    // Unselected first, so the selection is drawn on top.
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t i = 0; i < annotations_.traces.size(); ++i) {
        const bool selected =
            std::find(selectedTraces_.begin(), selectedTraces_.end(), i) != selectedTraces_.end();
        if (selected != (pass == 1)) continue;
        paintTrace(painter, annotations_.traces[i], selected, hoveredTrace_ == i);
      }
    paintKnots(painter);
  }
  paintDraft(painter);
  if (bandStart_ && !band_.isEmpty()) {
    painter.setPen(pen(QColor(120, 190, 255), 1, Qt::DashLine));
    painter.setBrush(QColor(120, 190, 255, 40));
    painter.drawRect(band_);
  }
}

void AnnotationLayer::paintTrace(QPainter& painter, const RingTrace& trace, bool selected,
                                 bool hovered) const {
  if (trace.points.size() < 2) return;
  const QRectF face = view_->faceRect(trace.face);
  if (!face.intersects(view_->rect())) return;
  QPolygonF line;
  line.reserve(static_cast<int>(trace.points.size()));
  for (glm::vec2 p : trace.points) line << toWidget(trace.face, p);
  painter.save();
  painter.setClipRect(face.adjusted(-1, -1, 1, 1).intersected(QRectF(view_->rect())));
  const QColor color = trace.origin == TraceOrigin::Detected ? kDetectedColor : kDrawnColor;
  const qreal width = selected ? 2.6 : hovered ? 2.4 : 1.6;
  // A dark halo keeps the line readable on light and dark wood; the selection gets a white one.
  painter.setPen(pen(selected ? QColor(255, 255, 255, 230) : kHalo, width + (selected ? 3.0 : 1.6)));
  painter.drawPolyline(line);
  painter.setPen(pen(hovered && !selected ? color.lighter(130) : color, width));
  painter.drawPolyline(line);
  if (selected) {  // the ends, where joins happen
    painter.setPen(pen(Qt::black, 1));
    painter.setBrush(Qt::white);
    painter.drawEllipse(line.front(), 3, 3);
    painter.drawEllipse(line.back(), 3, 3);
  }
  if (trace.year) {
    // The year number at the middle of the trace, on a dark tag.
    const std::vector<glm::vec2> even = resamplePolyline(trace.points, polylineLength(trace.points) / 2);
    const QPointF mid = toWidget(trace.face, even.size() >= 2 ? even[even.size() / 2] : trace.points.front());
    QFont font = painter.font();
    font.setPixelSize(11);
    font.setBold(true);
    painter.setFont(font);
    const QString text = QString::number(*trace.year);
    const QRectF box(mid.x() - 4 - 3.5 * text.size(), mid.y() - 8, 8 + 7 * text.size(), 16);
    painter.setPen(pen(color, 1));
    painter.setBrush(QColor(0, 0, 0, 190));
    painter.drawRoundedRect(box, 4, 4);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, text);
  }
  painter.restore();
}

// The knot's edge as an ellipse in the face's true scale, thin and solid: what the fit made the knot's
// surface pass through.
void AnnotationLayer::paintKnotOutlines(QPainter& painter) const {
  for (std::size_t k = 0; k < annotations_.knots.size(); ++k) {
    const KnotOutline* o = outlineOfMark(k);
    if (!o || (draggedKnot_ == k && knotMoved_)) continue;
    const double px = pxPerMm(o->face);
    painter.save();
    painter.setClipRect(view_->faceRect(o->face).intersected(QRectF(view_->rect())));
    painter.translate(toWidget(o->face, o->center));
    painter.rotate(qRadiansToDegrees(double(o->angleRad)));
    painter.setBrush(Qt::NoBrush);
    const QPointF zero(0, 0);
    painter.setPen(pen(kHalo, 3.0));
    painter.drawEllipse(zero, o->semiAxesMm.x * px, o->semiAxesMm.y * px);
    painter.setPen(pen(kKnotColor.lighter(125), 1.4));
    painter.drawEllipse(zero, o->semiAxesMm.x * px, o->semiAxesMm.y * px);
    painter.restore();
  }
}

void AnnotationLayer::paintKnots(QPainter& painter) const {
  paintKnotOutlines(painter);
  const auto& knots = annotations_.knots;
  // The marks of one knot joined by a dashed line (across the cross when they are on two faces).
  for (std::size_t a = 0; a < knots.size(); ++a)
    for (std::size_t b = a + 1; b < knots.size(); ++b) {
      if (knots[a].knot != knots[b].knot) continue;
      const QPointF p = toWidget(knots[a].face, knots[a].point), q = toWidget(knots[b].face, knots[b].point);
      painter.setPen(pen(kHalo, 3.5));
      painter.drawLine(p, q);
      painter.setPen(pen(kKnotColor, 1.6, Qt::DashLine));
      painter.drawLine(p, q);
    }
  QFont font = painter.font();
  font.setPixelSize(11);
  font.setBold(true);
  painter.setFont(font);
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const QPointF p = toWidget(knots[k].face, knots[k].point);
    const bool selected = std::find(selectedKnots_.begin(), selectedKnots_.end(), k) != selectedKnots_.end();
    const qreal r = hoveredKnot_ == k ? 8 : 6.5;
    // How far the fitted axis may pass from the mark (issue 19 item 1); a released mark holds nothing.
    const qreal accuracyPx = knots[k].accuracyMm * pxPerMm(knots[k].face);
    if (!knots[k].released && accuracyPx > r + 2) {
      painter.setBrush(Qt::NoBrush);
      painter.setPen(pen(kHalo, 2.5));
      painter.drawEllipse(p, accuracyPx, accuracyPx);
      painter.setPen(pen(kKnotColor, 1.2, Qt::DashLine));
      painter.drawEllipse(p, accuracyPx, accuracyPx);
    }
    painter.setPen(pen(selected ? Qt::white : QColor(0, 0, 0, 200), selected ? 3 : 1.5));
    painter.setBrush(knots[k].released ? QBrush(Qt::NoBrush) : QBrush(kKnotColor));
    painter.drawEllipse(p, r, r);
    painter.setPen(pen(Qt::black, 1.2));
    painter.drawLine(p - QPointF(r * 0.5, 0), p + QPointF(r * 0.5, 0));
    painter.drawLine(p - QPointF(0, r * 0.5), p + QPointF(0, r * 0.5));
    const QString label =
        knots[k].released ? tr("K%1 free").arg(knots[k].knot + 1) : tr("K%1").arg(knots[k].knot + 1);
    const QRectF box(p.x() + r + 2, p.y() - r - 12, 8 + 7 * label.size(), 15);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 170));
    painter.drawRoundedRect(box, 3, 3);
    painter.setPen(kKnotColor.lighter(140));
    painter.drawText(box, Qt::AlignCenter, label);
  }
}

void AnnotationLayer::paintDraft(QPainter& painter) const {
  if (draft_.empty() || !draftFace_) return;
  QPolygonF line;
  for (glm::vec2 p : draft_) line << toWidget(*draftFace_, p);
  if (tool_ == Tool::Polyline && cursor_) line << toWidget(*draftFace_, clampToFace(*draftFace_, *cursor_));
  painter.setPen(pen(kHalo, 3.6));
  painter.drawPolyline(line);
  painter.setPen(pen(kDraftColor, 1.8, tool_ == Tool::Polyline ? Qt::DashLine : Qt::SolidLine));
  painter.drawPolyline(line);
  if (tool_ == Tool::Polyline) {
    painter.setPen(pen(Qt::black, 1));
    painter.setBrush(kDraftColor);
    for (glm::vec2 p : draft_) painter.drawEllipse(toWidget(*draftFace_, p), 3, 3);
  }
}

}  // namespace kerf
