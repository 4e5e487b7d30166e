#include "board_controls.hpp"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace kerf {

BoardControls::BoardControls(QWidget* parent) : QWidget(parent) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(4, 4, 4, 4);
  const QString rows[] = {tr("Centre (mm)"), tr("Size (mm)"), tr("Rotation (°)")};
  const QString rowTips[] = {
      tr("Where the board's centre lies in the log: x, y across the log (the pith of the middle slice at "
         "0, 0), z up the log from its butt end"),
      tr("The board's width, length (along the grain when unrotated: up the log) and thickness"),
      tr("Turns of the board about its own width axis (rx), the log axis (ry, e.g. to face other knots) "
         "and its thickness axis (rz, e.g. a board cut across the log); rz first, then rx, then ry")};
  const QString columns[] = {QStringLiteral("x / w / rx"), QStringLiteral("y / l / ry"),
                             QStringLiteral("z / t / rz")};
  for (int c = 0; c < 3; ++c) grid->addWidget(new QLabel(columns[c], this), 0, c + 1, Qt::AlignCenter);
  for (int r = 0; r < 3; ++r) {
    auto* label = new QLabel(rows[r], this);
    label->setToolTip(rowTips[r]);
    grid->addWidget(label, r + 1, 0);
    for (int c = 0; c < 3; ++c) {
      auto* box = new QDoubleSpinBox(this);
      box->setKeyboardTracking(false);
      box->setDecimals(1);
      box->setToolTip(rowTips[r]);
      if (r == 0) {
        box->setRange(-5000.0, 10000.0);
        box->setSingleStep(5.0);
        box->setSuffix(QStringLiteral(" mm"));
      } else if (r == 1) {
        box->setRange(1.0, 2000.0);
        box->setSingleStep(5.0);
        box->setSuffix(QStringLiteral(" mm"));
      } else {
        box->setRange(-360.0, 360.0);
        box->setSingleStep(5.0);
        box->setSuffix(QStringLiteral("°"));
        box->setWrapping(true);
      }
      boxes_[r * 3 + c] = box;
      grid->addWidget(box, r + 1, c + 1);
      connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!updating_) emit boardEdited(board(), true);
      });
    }
  }
  auto* reset = new QPushButton(tr("Flat-sawn through knots"), this);
  reset->setToolTip(
      tr("Back to the default board: 110 × 110 × 30 mm, flat-sawn, face A 30 mm from the pith "
         "in the knottiest section of the log"));
  connect(reset, &QPushButton::clicked, this, &BoardControls::defaultBoardRequested);
  grid->addWidget(reset, 4, 0, 1, 4);
  grid->setRowStretch(5, 1);
}

void BoardControls::setBoard(const Board& board) {
  updating_ = true;
  for (int c = 0; c < 3; ++c) {
    boxes_[c]->setValue(board.center[c]);
    boxes_[3 + c]->setValue(board.size[c]);
    boxes_[6 + c]->setValue(board.rotationDeg[c]);
  }
  updating_ = false;
}

Board BoardControls::board() const {
  Board board;
  for (int c = 0; c < 3; ++c) {
    board.center[c] = static_cast<float>(boxes_[c]->value());
    board.size[c] = static_cast<float>(boxes_[3 + c]->value());
    board.rotationDeg[c] = static_cast<float>(boxes_[6 + c]->value());
  }
  return board;
}

}  // namespace kerf
