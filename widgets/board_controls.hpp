#pragma once
// Numeric placement of a board in a log: centre (log mm), size (width, length, thickness, mm) and the
// three rotations (degrees) of render/board_renderer.hpp, with a button back to the default flat-sawn
// board. Each typed value emits boardEdited(board, true); setBoard() never emits.
#include <QWidget>
#include <array>

#include "render/board_renderer.hpp"

class QDoubleSpinBox;

namespace kerf {

class BoardControls : public QWidget {
  Q_OBJECT

 public:
  explicit BoardControls(QWidget* parent = nullptr);

  void setBoard(const Board& board);
  Board board() const;
  // The spin box of centre (0..2), size (3..5) or rotation (6..8) component i (tests).
  QDoubleSpinBox* spinBox(int i) const { return boxes_[i]; }

 signals:
  void boardEdited(kerf::Board board, bool finished);
  void defaultBoardRequested();

 private:
  std::array<QDoubleSpinBox*, 9> boxes_{};
  bool updating_ = false;
};

}  // namespace kerf
