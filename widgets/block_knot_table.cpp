#include "block_knot_table.hpp"

#include <QHeaderView>
#include <QTableWidget>
#include <cmath>

#include "field/block_knot_shape.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

namespace kerf {

namespace {

QList<KnotTableBase::Column> blockColumns() {
  return {
      {BlockKnotTable::tr("Knot"),
       BlockKnotTable::tr("The knot's name: its marks on the faces carry it (K1, K2, …); selecting the row "
                          "selects its marks")},
      {BlockKnotTable::tr("Height\nmm"),
       BlockKnotTable::tr("Where the branch leaves the pith: mm along the pith from the level of the block's "
                          "centre (+: towards the top of the tree)")},
      {BlockKnotTable::tr("Angle\n°"),
       BlockKnotTable::tr("The angle between the branch and the pith, degrees: 90 runs straight out of the "
                          "stem, less rises towards the top of the tree (most branches: 50-80)")},
      {BlockKnotTable::tr("Around\n°"),
       BlockKnotTable::tr("Which way the branch runs around the pith, degrees; the faces it comes out on "
                          "are in the Ø column")},
      {BlockKnotTable::tr("Growth"),
       BlockKnotTable::tr("How fast the branch thickens: its radius per mm of the stem's radius near the "
                          "pith (0.1: a knot 2 mm across 10 mm from the pith); between 0 and 1")},
      {BlockKnotTable::tr("Taper"),
       BlockKnotTable::tr("How the branch's thickening slows as the tree grows: 0 a straight cone from the "
                          "pith, towards 0.95 a branch that nearly stopped thickening, as dying ones do")},
      {BlockKnotTable::tr("Ø mm\non faces"),
       BlockKnotTable::tr(
           "Where the knot comes out of the block and how thick it is there: face letter and "
           "diameter across the branch, whole mm (the cell's tooltip has tenths and the tree's age there)")},
      {BlockKnotTable::tr("Dead"),
       BlockKnotTable::tr(
           "Whether the branch died: from then on it stops thickening and is encased, a "
           "loose knot with a dark bark ring; alive, it stays intergrown with the stem's rings "
           "(Space toggles)")},
      {BlockKnotTable::tr("Died at\nyears"),
       BlockKnotTable::tr("When the branch died: the tree's age in years counted from the pith (rings from "
                          "the pith to where the knot's bark ring lies)")}};
}

}  // namespace

QString BlockKnotTable::knotName(int id) {
  return QStringLiteral("K%1").arg(id + 1);  // as the marks are labelled (annotation_layer.cpp)
}

BlockKnotTable::BlockKnotTable(QWidget* parent)
    : KnotTableBase(blockColumns(), {},
                    tr("Remove the selected knot from the block (Del); its marks stay on the faces, and the "
                       "next fit finds it again"),
                    parent) {
  table()->verticalHeader()->hide();  // the Knot column names the rows
}

void BlockKnotTable::setModel(std::shared_ptr<const WoodModel> model) {
  model_ = std::move(model);
  fill();
}

void BlockKnotTable::fill() {
  knots_ = model_ ? model_->knots().knots() : std::vector<BlockKnot>{};
  beginRows(static_cast<int>(knots_.size()));
  for (int k = 0; k < static_cast<int>(knots_.size()); ++k) {
    const BlockKnot& knot = knots_[k];
    const GrowthField& field = model_->field();
    const BlockKnotShape s = describeBlockKnot(knot, field.axis());
    setText(k, Id, knotName(knot.id));
    setNumber(k, Height, s.heightMm, 1);
    setNumber(k, Angle, s.angleToPithDeg, 1);
    setNumber(k, Around, s.aroundDeg, 1);
    setNumber(k, Speed, s.speed, 3);
    setNumber(k, Taper, s.taper, 2);
    QStringList cells, tips;
    for (const KnotCrossing& c : knotCrossings(knot, model_->block(), field, model_->knots().settings())) {
      cells << QStringLiteral("%1 %2").arg(QChar(faceLetter(c.face))).arg(c.diameterMm, 0, 'f', 0);
      tips << tr("face %1: %2 mm across, %3 years from the pith")
                  .arg(QChar(faceLetter(c.face)))
                  .arg(c.diameterMm, 0, 'f', 1)
                  .arg(c.stemYears, 0, 'f', 1);
    }
    setText(k, Faces, cells.isEmpty() ? tr("inside") : cells.join(QStringLiteral(" · ")),
            cells.isEmpty() ? tr("The knot's axis does not reach a face of the block")
                            : tr("Comes out on %1").arg(tips.join(tr("; "))));
    const QString deathTip =
        knot.dead() ? tr("Died %1 years from the pith: about %2 mm out at this block's %3 mm rings")
                          .arg(knot.deathTime, 0, 'f', 1)
                          .arg(knot.deathTime * field.ringWidth(), 0, 'f', 1)
                          .arg(field.ringWidth(), 0, 'f', 2)
                    : tr("Alive: tick Dead to let the branch die");
    setDeath(k, Dead, DiedAt, knot.deathTime, deathTip);
  }
  endRows();
}

QString BlockKnotTable::refusal(int column, double value) const {
  if (!std::isfinite(value)) return tr("Give a number");
  switch (column) {
    case Angle:
      if (!(value > 0.0 && value < 180.0))
        return tr("A branch leaves the pith at an angle between 0 and 180 degrees (90: straight out); %1 "
                  "would run along the pith")
            .arg(value);
      break;
    case Speed:
      if (!(value > 0.0 && value < 1.0))
        return tr("A branch thickens slower than the stem: its growth lies between 0 and 1 (0.1: 2 mm across "
                  "10 mm from the pith), not %1")
            .arg(value);
      break;
    case Taper:
      if (!(std::abs(value) <= kMaxKnotTaper))
        return tr("The taper lies between -%1 and %1 (0: a straight cone; near 1: a branch that stopped "
                  "thickening), not %2")
            .arg(static_cast<double>(kMaxKnotTaper))
            .arg(value);
      break;
    case DiedAt:
      if (!(value > 0.0))
        return tr("A branch cannot die before it starts at the pith (0 years): give the tree's age when it "
                  "died, more than 0 years, not %1")
            .arg(value);
      break;
    default:
      break;
  }
  return {};
}

void BlockKnotTable::cellEdited(int row, int column) {
  if (!model_ || row >= static_cast<int>(knots_.size())) return;
  const BlockKnot& knot = knots_[row];
  const PithAxis& pith = model_->field().axis();
  BlockKnotShape s = describeBlockKnot(knot, pith);
  const double v = number(row, column);
  if (column != Dead) {
    if (const QString why = refusal(column, v); !why.isEmpty()) {
      fill();  // back to the knot as it is
      refuse(row, column, why);
      return;
    }
  }
  const auto f = static_cast<float>(v);
  switch (column) {
    case Height:
      s.heightMm = f;
      break;
    case Angle:
      s.angleToPithDeg = f;
      break;
    case Around:
      s.aroundDeg = f;
      break;
    case Speed:
      s.speed = f;
      break;
    case Taper:
      s.taper = f;
      break;
    case Dead: {
      const bool dead = isChecked(row, Dead);
      if (dead == knot.dead()) return;
      s.deathYears = dead ? middleStemYears(knot, model_->block(), model_->field())
                          : std::numeric_limits<float>::infinity();
      break;
    }
    case DiedAt:
      if (!knot.dead()) return;
      s.deathYears = f;
      break;
    default:
      return;
  }
  const BlockKnot edited = reshapeBlockKnot(knot, s, pith);
  try {
    validate(edited, tr("knot %1").arg(knotName(knot.id)).toStdString());
  } catch (const InputError& e) {
    fill();
    refuse(row, column, QString::fromUtf8(e.what()));
    return;
  }
  emit knotEdited(row, edited);
}

}  // namespace kerf
