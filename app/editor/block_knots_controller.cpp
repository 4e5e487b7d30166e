#include "block_knots_controller.hpp"

#include <QDockWidget>
#include <set>

#include "annotation_layer.hpp"
#include "block_knot_table.hpp"
#include "document.hpp"
#include "util/error.hpp"

namespace kerf {

BlockKnotsController::BlockKnotsController(const EditorContext& context, BlockKnotTable* table,
                                           QDockWidget* dock, AnnotationLayer* annotationLayer)
    : EditorController(context), table_(table), dock_(dock), annotationLayer_(annotationLayer) {
  connect(document_, &Document::documentReset, this, [this] { showKnots(true); });
  connect(document_, &Document::modelChanged, this, [this] { showKnots(false); });
  connect(table_, &BlockKnotTable::knotEdited, this, &BlockKnotsController::editKnot);
  connect(table_, &BlockKnotTable::deleteRequested, this, &BlockKnotsController::deleteKnot);
  connect(table_, &BlockKnotTable::knotSelected, this, &BlockKnotsController::selectMarksOf);
  connect(table_, &BlockKnotTable::valueRefused, this,
          [this](const QString& why) { emit statusShown(why, 8000); });
  connect(annotationLayer_, &AnnotationLayer::selectionChanged, this,
          &BlockKnotsController::selectRowOfMarks);
}

void BlockKnotsController::showKnots(bool newDocument) {
  table_->setModel(document_->model());
  const bool hasKnots = !document_->project().knots.empty();
  // Shown when knots come (a document with knots opens, a fit brings the first ones); hidden with a document
  // without any, never under the user's hands (a deleted last knot leaves the empty table, which undo fills
  // again; saving leaves the dock as the user left it).
  if (newDocument && !hasKnots) dock_->hide();
  if (hasKnots && !hadKnots_) dock_->show();
  hadKnots_ = hasKnots;
}

void BlockKnotsController::editKnot(int row, const BlockKnot& knot) {
  std::vector<BlockKnot> knots = document_->project().knots;
  if (row < 0 || row >= static_cast<int>(knots.size())) return;
  knots[row] = knot;
  try {
    document_->editBlockKnots(std::move(knots), tr("Edit knot %1").arg(BlockKnotTable::knotName(knot.id)));
  } catch (const InputError& e) {
    log("error", tr("The knot was not changed: %1").arg(QString::fromUtf8(e.what())));
    table_->setModel(document_->model());  // back to what is valid
  }
}

void BlockKnotsController::deleteKnot(int row) {
  std::vector<BlockKnot> knots = document_->project().knots;
  if (row < 0 || row >= static_cast<int>(knots.size())) return;
  const QString name = BlockKnotTable::knotName(knots[row].id);
  knots.erase(knots.begin() + row);
  document_->editBlockKnots(std::move(knots), tr("Delete knot %1").arg(name));
  emit statusShown(
      tr("Knot %1 deleted from the block; its marks stay on the faces (Ctrl+Z brings it back)").arg(name),
      5000);
}

void BlockKnotsController::selectMarksOf(int row) {
  if (row < 0 || row >= table_->knotCount()) return;
  const int id = table_->knotOf(row).id;
  std::vector<std::size_t> marks;
  const auto& all = document_->annotations().knots;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].knot == id) marks.push_back(i);
  selectingMarks_ = true;
  annotationLayer_->setSelection({}, std::move(marks));
  selectingMarks_ = false;
}

void BlockKnotsController::selectRowOfMarks() {
  if (selectingMarks_) return;
  const auto& all = document_->annotations().knots;
  std::set<int> ids;
  for (std::size_t i : annotationLayer_->selectedKnots())
    if (i < all.size()) ids.insert(all[i].knot);
  if (ids.size() != 1) return;
  for (int row = 0; row < table_->knotCount(); ++row)
    if (table_->knotOf(row).id == *ids.begin()) table_->setSelectedKnot(row);
}

}  // namespace kerf
