#pragma once
// The block's knots (field/block_knots.hpp: from the fit of the knot marks, or the project file) as a
// table a user can edit (docs/editor.md, "Knots in the block"): one row per knot with its name (K1: that
// of its marks), where it leaves the pith and at what angle and which way around it, how fast it thickens
// and tapers, where its axis comes out of the block and how thick it is there (read-only), and whether and
// when it died (years from the pith). An edited cell emits knotEdited(row, knot), a bad value is refused
// at its cell and emits nothing; Delete emits a request (knot_table_base.hpp). setModel() never emits an
// edit.
#include <memory>
#include <vector>

#include "field/block_knots.hpp"
#include "knot_table_base.hpp"

namespace kerf {

class WoodModel;

class BlockKnotTable : public KnotTableBase {
  Q_OBJECT

 public:
  enum Column { Id, Height, Angle, Around, Speed, Taper, Faces, Dead, DiedAt, ColumnCount };

  explicit BlockKnotTable(QWidget* parent = nullptr);

  // The model's knots, in words of its pith, ring width and block (a few knots: cheap to fill again).
  void setModel(std::shared_ptr<const WoodModel> model);
  // The name of knot `id` as its marks show it: K1 for id 0.
  static QString knotName(int id);
  int knotCount() const { return static_cast<int>(knots_.size()); }
  const BlockKnot& knotOf(int row) const { return knots_.at(static_cast<std::size_t>(row)); }

 signals:
  void knotEdited(int row, kerf::BlockKnot knot);

 private:
  void fill();
  void cellEdited(int row, int column) override;
  // Why `value` cannot go into `column` (empty: it can).
  QString refusal(int column, double value) const;

  std::shared_ptr<const WoodModel> model_;
  std::vector<BlockKnot> knots_;
};

}  // namespace kerf
