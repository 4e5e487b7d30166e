#include "knot_table.hpp"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace kerf {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

QTableWidgetItem* numberItem(double value) {
  auto* item = new QTableWidgetItem;
  item->setData(Qt::EditRole, std::round(value * 100.0) / 100.0);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

}  // namespace

KnotTable::KnotTable(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  table_ = new QTableWidget(0, ColumnCount, this);
  const QStringList headers = {tr("Height"), tr("Azimuth"), tr("Rise"), tr("Bend"),
                               tr("Twist"),  tr("Length"),  tr("Dead"), tr("Died at")};
  const QStringList tips = {
      tr("Where the branch leaves the pith, mm up the log"),
      tr("The branch's direction around the stem at the pith, degrees from +x towards +y"),
      tr("How steeply the branch climbs far from the pith: mm up per mm outward (spruce: 0.1-0.6)"),
      tr("The early upward bend near the pith, mm per √mm: branches of conifers turn up before they "
         "run out straight (0 = a straight branch)"),
      tr("How much the branch turns around the stem from the pith to its end, degrees"),
      tr("How far out from the pith the branch runs, mm"),
      tr("Whether the branch died (a dead, loose knot with a dark outline beyond that distance) or stayed "
         "alive (an intergrown knot) to the bark"),
      tr("Distance from the pith at which the branch died, mm: the tree's radius at the time of death")};
  table_->setHorizontalHeaderLabels(headers);
  for (int c = 0; c < ColumnCount; ++c) table_->horizontalHeaderItem(c)->setToolTip(tips[c]);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->verticalHeader()->setDefaultSectionSize(22);
  layout->addWidget(table_, 1);

  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton(tr("Add Knot"), this);
  add->setToolTip(tr("A new living branch at the board's height, pointing at the board"));
  delete_ = new QPushButton(tr("Delete Knot"), this);
  delete_->setEnabled(false);
  buttons->addWidget(add);
  buttons->addWidget(delete_);
  buttons->addStretch(1);
  layout->addLayout(buttons);

  connect(add, &QPushButton::clicked, this, &KnotTable::addRequested);
  connect(delete_, &QPushButton::clicked, this, [this] {
    if (selectedKnot() >= 0) emit deleteRequested(selectedKnot());
  });
  connect(table_, &QTableWidget::cellChanged, this, &KnotTable::cellEdited);
  connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
    delete_->setEnabled(selectedKnot() >= 0);
    if (!updating_) emit knotSelected(selectedKnot());
  });
}

void KnotTable::setKnots(const std::vector<Knot>& knots) {
  const int selected = selectedKnot();
  updating_ = true;
  shapes_.clear();
  table_->setRowCount(static_cast<int>(knots.size()));
  for (int k = 0; k < static_cast<int>(knots.size()); ++k) {
    const KnotShape s = describeKnot(knots[k]);
    shapes_.push_back(s);
    const bool dead = std::isfinite(s.deathDistanceMm);
    table_->setItem(k, Height, numberItem(s.heightMm));
    // Skeleton azimuths are unwrapped (may pass 360 degrees); show the direction in [0, 360).
    table_->setItem(k, Azimuth, numberItem(std::fmod(std::fmod(s.azimuthRad * kDeg, 360.0) + 360.0, 360.0)));
    table_->setItem(k, Rise, numberItem(s.rise));
    table_->setItem(k, Bend, numberItem(s.bend));
    table_->setItem(k, Twist, numberItem(s.twistRad * kDeg));
    table_->setItem(k, Length, numberItem(s.lengthMm));
    auto* deadItem = new QTableWidgetItem(dead ? tr("dead") : tr("alive"));
    deadItem->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
    deadItem->setCheckState(dead ? Qt::Checked : Qt::Unchecked);
    table_->setItem(k, Dead, deadItem);
    auto* death = dead ? numberItem(s.deathDistanceMm) : new QTableWidgetItem(QStringLiteral("—"));
    if (!dead) death->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(k, DeathDistance, death);
  }
  updating_ = false;
  if (selected >= 0 && selected < table_->rowCount()) setSelectedKnot(selected);
}

int KnotTable::selectedKnot() const {
  const auto rows = table_->selectionModel()->selectedRows();
  return rows.isEmpty() ? -1 : rows.front().row();
}

void KnotTable::setSelectedKnot(int knot) {
  updating_ = true;
  if (knot < 0 || knot >= table_->rowCount()) {
    table_->clearSelection();
  } else {
    table_->selectRow(knot);
    table_->scrollToItem(table_->item(knot, 0));
  }
  updating_ = false;
  delete_->setEnabled(selectedKnot() >= 0);
}

KnotShape KnotTable::shapeOf(int row) const {
  return shapes_.at(static_cast<std::size_t>(row));
}

void KnotTable::cellEdited(int row, int column) {
  if (updating_ || row < 0 || row >= static_cast<int>(shapes_.size())) return;
  KnotShape s = shapes_[row];
  const double v = table_->item(row, column)->data(Qt::EditRole).toDouble();
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
      const bool dead = table_->item(row, Dead)->checkState() == Qt::Checked;
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
