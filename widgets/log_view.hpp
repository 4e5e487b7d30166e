#pragma once
// The log seen from two sides, for placing a board in it (docs/editor.md, "Logs and boards"):
//  - left, the top view (looking down the log axis): the stem's outline at the board's height, the pith,
//    the knot skeletons (faded with their height away from the board) and the board's outline;
//  - right, the side view (the log axis horizontal, looking along the board's thickness so its face A is
//    seen face-on): the stem's outline and pith curve over the log's length, every knot skeleton and the
//    board.
// Knot skeletons are green where the branch was alive and brown where it was dead; the selected knot is
// yellow. Dragging moves the board (top view: across the log, side view: along it and across), Ctrl+drag
// in the top view turns it about the log axis; a click on a knot selects it. The wheel zooms the side view
// along the log. While dragging, boardEdited(board, false) is emitted for each step and
// boardEdited(board, true) once on release; setBoard() never emits.
#include <QWidget>
#include <memory>

#include "field/log_model.hpp"
#include "render/board_renderer.hpp"

namespace kerf {

class LogView : public QWidget {
  Q_OBJECT

 public:
  explicit LogView(QWidget* parent = nullptr);

  void setLog(std::shared_ptr<const LogModel> log);  // null: an empty view
  const std::shared_ptr<const LogModel>& log() const { return log_; }
  void setBoard(const Board& board);
  const Board& board() const { return board_; }
  void setSelectedKnot(int knot);  // -1: none
  int selectedKnot() const { return selected_; }

  // Where a log point lands on the widget, in the top and the side view (tests and hit testing).
  QPointF topViewPoint(const glm::vec3& logPoint) const;
  QPointF sideViewPoint(const glm::vec3& logPoint) const;

  QSize sizeHint() const override { return {720, 260}; }
  QSize minimumSizeHint() const override { return {240, 120}; }

 signals:
  void boardEdited(kerf::Board board, bool finished);
  void knotClicked(int knot);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  enum class Panel { None, Top, Side };
  struct Mapping {  // a panel: screen = origin + scale * (a, -b) for the panel's 2D log coordinates (a, b)
    QRectF rect;
    QPointF origin;
    double scale = 1.0;
  };
  Mapping topMapping() const;
  Mapping sideMapping() const;
  glm::vec3 sideAcross() const;  // the horizontal unit vector drawn upward in the side view
  Panel panelAt(QPointF p) const;
  int knotAt(QPointF p) const;  // the knot whose skeleton passes within a few pixels, or -1

  void paintTop(class QPainter& painter, const Mapping& m) const;
  void paintSide(class QPainter& painter, const Mapping& m) const;
  void paintBoard(class QPainter& painter, bool top) const;

  std::shared_ptr<const LogModel> log_;
  Board board_;
  int selected_ = -1;
  double sideSpanMm_ = 0.0;  // length of log shown in the side view (0: all of it)

  Panel dragPanel_ = Panel::None;
  bool dragRotates_ = false, dragMoved_ = false;
  QPointF pressPos_;
  Board pressBoard_;
};

}  // namespace kerf
