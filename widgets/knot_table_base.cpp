#include "knot_table_base.hpp"

#include <QAction>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QStyledItemDelegate>
#include <QTableWidget>
#include <QToolTip>
#include <QVBoxLayout>
#include <cmath>

namespace kerf {

namespace {

// Numbers are typed in a spin box with room for any value and three decimals (Qt's default box has two):
// the table refuses what does not fit the knot and says why, rather than the box clamping it unseen.
class NumberDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                        const QModelIndex& index) const override {
    if (index.data(Qt::EditRole).typeId() != QMetaType::Double)
      return QStyledItemDelegate::createEditor(parent, option, index);
    auto* box = new QDoubleSpinBox(parent);
    box->setFrame(false);
    box->setRange(-1e6, 1e6);
    box->setDecimals(3);
    return box;
  }
};

}  // namespace

KnotTableBase::KnotTableBase(const QList<Column>& columns, const QString& addTip, const QString& deleteTip,
                             QWidget* parent)
    : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  table_ = new QTableWidget(0, static_cast<int>(columns.size()), this);
  QStringList headers;
  for (const Column& c : columns) headers << c.header;
  table_->setHorizontalHeaderLabels(headers);
  for (int c = 0; c < columns.size(); ++c) table_->horizontalHeaderItem(c)->setToolTip(columns[c].tip);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->verticalHeader()->setDefaultSectionSize(22);
  table_->setItemDelegate(new NumberDelegate(table_));
  layout->addWidget(table_, 1);

  auto* buttons = new QHBoxLayout;
  if (!addTip.isEmpty()) {
    auto* add = new QPushButton(tr("Add Knot"), this);
    add->setToolTip(addTip);
    connect(add, &QPushButton::clicked, this, &KnotTableBase::addRequested);
    buttons->addWidget(add);
  }
  delete_ = new QPushButton(tr("Delete Knot"), this);
  delete_->setToolTip(deleteTip);
  delete_->setEnabled(false);
  buttons->addWidget(delete_);
  buttons->addStretch(1);
  layout->addLayout(buttons);

  const auto requestDelete = [this] {
    if (selectedKnot() >= 0) emit deleteRequested(selectedKnot());
  };
  connect(delete_, &QPushButton::clicked, this, requestDelete);
  auto* deleteKey = new QAction(this);  // Del while the table has the focus (the faces' Del is theirs)
  deleteKey->setShortcut(QKeySequence::Delete);
  deleteKey->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  connect(deleteKey, &QAction::triggered, this, requestDelete);
  addAction(deleteKey);
  connect(table_, &QTableWidget::cellChanged, this, [this](int row, int column) {
    if (updating_ || row < 0 || column < 0) return;
    QToolTip::hideText();
    cellEdited(row, column);
  });
  // A click on the selected row selects its knot again elsewhere (e.g. its marks, deselected since).
  connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) {
    if (!updating_ && row == selectedKnot()) emit knotSelected(row);
  });
  connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
    delete_->setEnabled(selectedKnot() >= 0);
    if (!updating_) emit knotSelected(selectedKnot());
  });
}

void KnotTableBase::beginRows(int count) {
  selectedBefore_ = selectedKnot();
  updating_ = true;
  table_->setRowCount(count);
}

void KnotTableBase::endRows() {
  updating_ = false;
  if (selectedBefore_ >= 0 && selectedBefore_ < table_->rowCount()) setSelectedKnot(selectedBefore_);
  delete_->setEnabled(selectedKnot() >= 0);
}

void KnotTableBase::setNumber(int row, int column, double value, int decimals, const QString& tip) {
  auto* item = new QTableWidgetItem;
  const double scale = std::pow(10.0, decimals);
  item->setData(Qt::EditRole, std::round(value * scale) / scale);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  if (!tip.isEmpty()) item->setToolTip(tip);
  table_->setItem(row, column, item);
}

void KnotTableBase::setText(int row, int column, const QString& text, const QString& tip) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
  if (!tip.isEmpty()) item->setToolTip(tip);
  table_->setItem(row, column, item);
}

void KnotTableBase::setDeath(int row, int deadColumn, int deathColumn, double death, const QString& tip) {
  const bool dead = std::isfinite(death);
  auto* deadItem = new QTableWidgetItem;  // the box alone: a narrow column
  deadItem->setToolTip(dead ? tr("Dead (Space: alive again)") : tr("Alive (Space: let it die)"));
  deadItem->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
  deadItem->setCheckState(dead ? Qt::Checked : Qt::Unchecked);
  table_->setItem(row, deadColumn, deadItem);
  if (dead)
    setNumber(row, deathColumn, death, 2, tip);
  else
    setText(row, deathColumn, QStringLiteral("—"), tip);
}

bool KnotTableBase::isChecked(int row, int column) const {
  return table_->item(row, column)->checkState() == Qt::Checked;
}

double KnotTableBase::number(int row, int column) const {
  return table_->item(row, column)->data(Qt::EditRole).toDouble();
}

void KnotTableBase::refuse(int row, int column, const QString& why) {
  lastRefusal_ = why;
  const QRect cell = table_->visualRect(table_->model()->index(row, column));
  QToolTip::showText(table_->viewport()->mapToGlobal(cell.bottomLeft()), why, table_->viewport());
  emit valueRefused(why);
}

int KnotTableBase::selectedKnot() const {
  const auto rows = table_->selectionModel()->selectedRows();
  return rows.isEmpty() ? -1 : rows.front().row();
}

void KnotTableBase::setSelectedKnot(int knot) {
  const bool was = updating_;
  updating_ = true;
  if (knot < 0 || knot >= table_->rowCount()) {
    table_->clearSelection();
  } else {
    table_->selectRow(knot);
    table_->scrollToItem(table_->item(knot, 0));
  }
  updating_ = was;
  delete_->setEnabled(selectedKnot() >= 0);
}

}  // namespace kerf
