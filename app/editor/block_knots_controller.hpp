#pragma once
// The block's knots in the editor (docs/editor.md, "Knots in the block"): the "Knots" dock's table
// (widgets/block_knot_table.hpp) follows the document's model (a fit that adds knots, undo, another
// document); an edited row or a deleted knot is one undo step of the growth field (Document::editBlockKnots),
// after which the faces, the 3D view and the cut are drawn again as after any parameter edit. A selected
// row selects its knot's marks on the faces, and selecting the marks of one knot selects its row. The dock
// appears when the document has knots.
#include "editor_controller.hpp"

class QDockWidget;

namespace kerf {

class AnnotationLayer;
class BlockKnotTable;
struct BlockKnot;

class BlockKnotsController : public EditorController {
  Q_OBJECT

 public:
  BlockKnotsController(const EditorContext& context, BlockKnotTable* table, QDockWidget* dock,
                       AnnotationLayer* annotationLayer);

 private:
  void showKnots(bool newDocument);
  void editKnot(int row, const BlockKnot& knot);
  void deleteKnot(int row);
  void selectMarksOf(int row);
  void selectRowOfMarks();

  BlockKnotTable* table_;
  QDockWidget* dock_;
  AnnotationLayer* annotationLayer_;
  bool hadKnots_ = false;
  bool selectingMarks_ = false;  // the row selects the marks: their selection does not select back
};

}  // namespace kerf
