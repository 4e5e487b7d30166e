#pragma once
// The log's knots as a table a user can edit (docs/editor.md, "Logs and boards"): one row per knot with
// its shape (field/knot_shape.hpp): where it leaves the pith (height, azimuth), how it rises, bends and
// twists, its length, and whether and where it died. An edited cell emits knotEdited(row, shape); Add and
// Delete emit requests (knot_table_base.hpp). setKnots() never emits an edit.
#include <vector>

#include "field/knot_shape.hpp"
#include "knot_table_base.hpp"

namespace kerf {

class KnotTable : public KnotTableBase {
  Q_OBJECT

 public:
  enum Column { Height, Azimuth, Rise, Bend, Twist, Length, Dead, DeathDistance, ColumnCount };

  explicit KnotTable(QWidget* parent = nullptr);

  void setKnots(const std::vector<Knot>& knots);
  // The shape a row shows (tests): what an edit of that row starts from.
  KnotShape shapeOf(int row) const;

 signals:
  void knotEdited(int knot, kerf::KnotShape shape);

 private:
  void cellEdited(int row, int column) override;

  std::vector<KnotShape> shapes_;
};

}  // namespace kerf
