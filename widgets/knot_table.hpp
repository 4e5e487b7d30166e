#pragma once
// The log's knots as a table a user can edit (docs/editor.md, "Logs and boards"): one row per knot with
// its shape (field/knot_shape.hpp): where it leaves the pith (height, azimuth), how it rises, bends and
// twists, its length, and whether and where it died. An edited cell emits knotEdited(row, shape); Add and
// Delete emit requests. setKnots() never emits an edit.
#include <QWidget>
#include <vector>

#include "field/knot_shape.hpp"

class QTableWidget;
class QPushButton;

namespace kerf {

class KnotTable : public QWidget {
  Q_OBJECT

 public:
  enum Column { Height, Azimuth, Rise, Bend, Twist, Length, Dead, DeathDistance, ColumnCount };

  explicit KnotTable(QWidget* parent = nullptr);

  void setKnots(const std::vector<Knot>& knots);
  int selectedKnot() const;  // -1: none
  void setSelectedKnot(int knot);
  QTableWidget* table() const { return table_; }
  // The shape a row shows (tests): what an edit of that row starts from.
  KnotShape shapeOf(int row) const;

 signals:
  void knotEdited(int knot, kerf::KnotShape shape);
  void addRequested();
  void deleteRequested(int knot);
  void knotSelected(int knot);

 private:
  void cellEdited(int row, int column);

  QTableWidget* table_ = nullptr;
  QPushButton* delete_ = nullptr;
  std::vector<KnotShape> shapes_;
  bool updating_ = false;
};

}  // namespace kerf
