// AnnotationLayer: editing knot marks (issue 19 item 1). A mark holds the fitted knot's axis within its
// accuracy unless released; Select drags a mark to where the knot's centre really comes out, R releases
// or holds the selected knots' marks, M sets how accurate they are, E drops (or takes back) the knot's edge
// found around them on the photo when it is wrong. Each edit is one undo step.
#include <QAction>
#include <QInputDialog>
#include <cmath>

#include "annotation_layer.hpp"
#include "faces_view.hpp"

namespace kerf {

namespace {
constexpr qreal kKnotDragStartPx = 3;  // a press that moves less is a click (selection only)
}

void AnnotationLayer::createKnotActions() {
  releaseKnotAction_ = makeEditAction(
      tr("Release"), QKeySequence(Qt::Key_R),
      tr("Let the rings place the selected knots: their marks then only say where to start. Press "
         "again to make the marks hold the knots (R)"));
  knotAccuracyAction_ = makeEditAction(
      tr("Mark ±mm"), QKeySequence(Qt::Key_M),
      tr("How sure you are of where the selected knots come out: the fitted knot passes within this "
         "many mm of each mark, drawn as the dashed circle (M)"));
  knotEdgeAction_ = makeEditAction(
      tr("No Edge"), QKeySequence(Qt::Key_E),
      tr("The knot's edge found around the selected marks on the photo is wrong (a resin streak, a shadow or "
         "a check beside the knot): do not size the knot by it, let the rings size it. Press again to use "
         "the edge (E)"));
  connect(releaseKnotAction_, &QAction::triggered, this, &AnnotationLayer::toggleReleaseOfSelectedKnots);
  connect(knotEdgeAction_, &QAction::triggered, this, &AnnotationLayer::toggleIgnoredEdgeOfSelectedKnots);
  connect(knotAccuracyAction_, &QAction::triggered, this, &AnnotationLayer::askKnotAccuracyForSelection);
}

void AnnotationLayer::setKnotOutlines(std::vector<KnotOutline> outlines) {
  knotOutlines_ = std::move(outlines);
  view_->update();
}

const KnotOutline* AnnotationLayer::outlineOfMark(std::size_t knot) const {
  if (knot >= annotations_.knots.size()) return nullptr;
  const KnotMark& m = annotations_.knots[knot];
  if (m.ignoreEdge) return nullptr;  // not drawn, not said, until the fit's next outlines
  for (const KnotOutline& o : knotOutlines_)
    if (o.found && o.knot == m.knot && o.face == m.face && o.seed == m.point) return &o;
  return nullptr;
}

QString AnnotationLayer::knotMarkText(std::size_t knot) const {
  const KnotMark& m = annotations_.knots[knot];
  const KnotOutline* o = outlineOfMark(knot);
  const QString edge = m.ignoreEdge
                           ? tr(" Its edge on the photo is ignored: the rings size the knot (E uses it "
                                "again).")
                       : o ? tr(" Its edge on the photo: %1 x %2 mm (the fitted knot's size follows it; E "
                                "ignores a wrong edge).")
                                 .arg(2.0 * o->semiAxesMm.x, 0, 'f', 1)
                                 .arg(2.0 * o->semiAxesMm.y, 0, 'f', 1)
                           : QString();
  if (m.released)
    return tr("Knot K%1 on face %2: released, the rings place the knot and this mark only says where to "
              "start (R holds it again; drag to move it)")
               .arg(m.knot + 1)
               .arg(QChar(faceLetter(m.face))) +
           edge;
  return tr("Knot K%1 on face %2: the fitted knot passes within %3 mm of this mark (drag to move it; M "
            "changes how close, R lets the rings place the knot)")
             .arg(m.knot + 1)
             .arg(QChar(faceLetter(m.face)))
             .arg(double(m.accuracyMm), 0, 'g', 3) +
         edge;
}

void AnnotationLayer::startKnotDrag(std::size_t knot, QPointF widgetPos) {
  draggedKnot_ = knot;
  draggedKnotFrom_ = annotations_.knots[knot].point;
  knotPress_ = widgetPos;
  knotMoved_ = false;
}

void AnnotationLayer::moveKnotDrag(QPointF widgetPos) {
  if (!draggedKnot_ || *draggedKnot_ >= annotations_.knots.size()) return;
  if (!knotMoved_ &&
      std::hypot(widgetPos.x() - knotPress_.x(), widgetPos.y() - knotPress_.y()) < kKnotDragStartPx)
    return;
  knotMoved_ = true;
  KnotMark& mark = annotations_.knots[*draggedKnot_];  // shown moved; the document gets it on release
  mark.point = clampToFace(mark.face, widgetPos);
  emit message(tr("Knot K%1 on face %2 at %3, %4 mm")
                   .arg(mark.knot + 1)
                   .arg(QChar(faceLetter(mark.face)))
                   .arg(double(mark.point.x), 0, 'f', 1)
                   .arg(double(mark.point.y), 0, 'f', 1));
  view_->update();
}

void AnnotationLayer::finishKnotDrag() {
  const std::optional<std::size_t> knot = draggedKnot_;
  const bool moved = knotMoved_;
  draggedKnot_.reset();
  knotMoved_ = false;
  if (!knot || !moved || *knot >= annotations_.knots.size()) return;
  Annotations after = annotations_;
  annotations_.knots[*knot].point = draggedKnotFrom_;  // the edit is the document's to apply
  emitEdit(std::move(after), tr("Move Knot Mark"), {}, selectedKnots_);
}

bool AnnotationLayer::cancelKnotDrag() {
  if (!draggedKnot_) return false;
  if (knotMoved_ && *draggedKnot_ < annotations_.knots.size())
    annotations_.knots[*draggedKnot_].point = draggedKnotFrom_;
  draggedKnot_.reset();
  knotMoved_ = false;
  emit message(tr("Knot mark left where it was."));
  view_->update();
  return true;
}

// A yes/no of the selected knot marks as one undo step: on for all when any is off, off when all are on.
void AnnotationLayer::toggleSelectedKnotFlag(bool KnotMark::*flag, const FlagTexts& on,
                                             const FlagTexts& off) {
  if (selectedKnots_.empty()) {
    emit message(tr("Select a knot mark first (Select, V)."));
    return;
  }
  bool set = false;
  for (std::size_t k : selectedKnots_) set = set || !(annotations_.knots[k].*flag);
  Annotations after = annotations_;
  for (std::size_t k : selectedKnots_) after.knots[k].*flag = set;
  const FlagTexts& texts = set ? on : off;
  emitEdit(std::move(after), texts.undo, {}, selectedKnots_);
  emit message(texts.status);
}

void AnnotationLayer::toggleReleaseOfSelectedKnots() {
  toggleSelectedKnotFlag(
      &KnotMark::released,
      {tr("Release Knot Marks"),
       tr("The rings place these knots now; their marks only say where to start (R holds them again).")},
      {tr("Hold Knots by Their Marks"), tr("The marks hold these knots again.")});
}

void AnnotationLayer::toggleIgnoredEdgeOfSelectedKnots() {
  toggleSelectedKnotFlag(
      &KnotMark::ignoreEdge,
      {tr("Ignore Knot Edges"),
       tr("The rings size these knots now, not their edges on the photos (E uses the edges again).")},
      {tr("Use Knot Edges"), tr("The knots' edges on the photos size them again.")});
}

void AnnotationLayer::setSelectedKnotAccuracy(float mm) {
  if (selectedKnots_.empty()) return;
  Annotations after = annotations_;
  for (std::size_t k : selectedKnots_) {
    after.knots[k].accuracyMm = mm;
    after.knots[k].released = false;  // an accuracy is for a mark that holds
  }
  emitEdit(std::move(after), tr("Knot Marks ±%1 mm").arg(double(mm), 0, 'g', 3), {}, selectedKnots_);
}

void AnnotationLayer::askKnotAccuracyForSelection() {
  if (selectedKnots_.empty()) {
    emit message(tr("Select a knot mark first (Select, V)."));
    return;
  }
  QInputDialog* dialog = openDialog("knotAccuracyDialog", tr("Knot Mark Accuracy"));
  dialog->setInputMode(QInputDialog::DoubleInput);
  dialog->setDoubleRange(0.05, 50.0);
  dialog->setDoubleDecimals(2);
  dialog->setDoubleValue(annotations_.knots[selectedKnots_.front()].accuracyMm);
  dialog->setLabelText(
      tr("How sure are you of where the knot's centre comes out, in mm?\nThe fitted knot passes within "
         "this distance of the selected marks (0.05-50)."));
  connect(dialog, &QInputDialog::doubleValueSelected, this,
          [this](double mm) { setSelectedKnotAccuracy(static_cast<float>(mm)); });
  dialog->open();
}

}  // namespace kerf
