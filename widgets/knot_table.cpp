#include "knot_table.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace kerf {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

QList<KnotTableBase::Column> logColumns() {
  return {
      {KnotTable::tr("Height"), KnotTable::tr("Where the branch leaves the pith, mm up the log")},
      {KnotTable::tr("Azimuth"),
       KnotTable::tr("The branch's direction around the stem at the pith, degrees from +x towards +y")},
      {KnotTable::tr("Rise"),
       KnotTable::tr(
           "How steeply the branch climbs far from the pith: mm up per mm outward (spruce: 0.1-0.6)")},
      {KnotTable::tr("Bend"),
       KnotTable::tr("The early upward bend near the pith, mm per √mm: branches of conifers turn up before "
                     "they run out straight (0 = a straight branch)")},
      {KnotTable::tr("Twist"),
       KnotTable::tr("How much the branch turns around the stem from the pith to its end, degrees")},
      {KnotTable::tr("Length"), KnotTable::tr("How far out from the pith the branch runs, mm")},
      {KnotTable::tr("Dead"),
       KnotTable::tr("Whether the branch died (a dead, loose knot with a dark outline beyond that distance) "
                     "or stayed alive (an intergrown knot) to the bark")},
      {KnotTable::tr("Died at"),
       KnotTable::tr("Distance from the pith at which the branch died, mm: the tree's radius at the time of "
                     "death")}};
}

}  // namespace

KnotTable::KnotTable(QWidget* parent)
    : KnotTableBase(logColumns(), tr("A new living branch at the board's height, pointing at the board"),
                    tr("Remove the selected branch from the log (Del)"), parent) {}

void KnotTable::setKnots(const std::vector<Knot>& knots) {
  beginRows(static_cast<int>(knots.size()));
  shapes_.clear();
  for (int k = 0; k < static_cast<int>(knots.size()); ++k) {
    const KnotShape s = describeKnot(knots[k]);
    shapes_.push_back(s);
    setNumber(k, Height, s.heightMm);
    // Skeleton azimuths are unwrapped (may pass 360 degrees); show the direction in [0, 360).
    setNumber(k, Azimuth, std::fmod(std::fmod(s.azimuthRad * kDeg, 360.0) + 360.0, 360.0));
    setNumber(k, Rise, s.rise);
    setNumber(k, Bend, s.bend);
    setNumber(k, Twist, s.twistRad * kDeg);
    setNumber(k, Length, s.lengthMm);
    setDeath(k, Dead, DeathDistance, s.deathDistanceMm);
  }
  endRows();
}

KnotShape KnotTable::shapeOf(int row) const {
  return shapes_.at(static_cast<std::size_t>(row));
}

void KnotTable::cellEdited(int row, int column) {
  if (row >= static_cast<int>(shapes_.size())) return;
  KnotShape s = shapes_[row];
  const double v = number(row, column);
  switch (column) {
    case Height:
      s.heightMm = static_cast<float>(v);
      break;
    case Azimuth:
      s.azimuthRad = static_cast<float>(v / kDeg);
      break;
    case Rise:
      s.rise = static_cast<float>(v);
      break;
    case Bend:
      s.bend = static_cast<float>(v);
      break;
    case Twist:
      s.twistRad = static_cast<float>(v / kDeg);
      break;
    case Length:
      s.lengthMm = static_cast<float>(std::max(v, 1.0));
      break;
    case Dead: {
      const bool dead = isChecked(row, Dead);
      if (dead == std::isfinite(s.deathDistanceMm)) return;
      s.deathDistanceMm = dead ? 0.5f * s.lengthMm : std::numeric_limits<float>::infinity();
      break;
    }
    case DeathDistance:
      if (!std::isfinite(s.deathDistanceMm)) return;
      s.deathDistanceMm = static_cast<float>(std::max(v, 0.0));
      break;
    default:
      return;
  }
  emit knotEdited(row, s);
}

}  // namespace kerf
