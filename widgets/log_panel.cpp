#include "log_panel.hpp"

#include <QApplication>
#include <QClipboard>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QShortcut>
#include <QVBoxLayout>
#include <memory>

namespace kerf {

namespace {

enum class Level { Info, Warning, Error };
constexpr int kLevelRole = Qt::UserRole + 1;

Level levelOf(const QString& level) {
  if (level.compare(QLatin1String("error"), Qt::CaseInsensitive) == 0) return Level::Error;
  if (level.compare(QLatin1String("warning"), Qt::CaseInsensitive) == 0) return Level::Warning;
  return Level::Info;
}

QColor colorOf(Level level, const QPalette& palette) {
  switch (level) {
    case Level::Error:
      return {220, 60, 50};
    case Level::Warning:
      return {214, 140, 20};
    case Level::Info:
      break;
  }
  return palette.color(QPalette::Text);
}

}  // namespace

LogPanel::LogPanel(QWidget* parent) : QWidget(parent) {
  list_ = new QListWidget(this);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  list_->setUniformItemSizes(true);
  list_->setWordWrap(false);
  QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  list_->setFont(mono);
  badge_ = new QLabel(this);
  badge_->setStyleSheet(
      QStringLiteral("QLabel { color: white; background: #c8372d; border-radius: 7px; "
                     "padding: 0px 6px; font-weight: bold; }"));
  badge_->setVisible(false);
  clear_ = new QPushButton(tr("Clear"), this);
  copy_ = new QPushButton(tr("Copy"), this);
  copy_->setToolTip(tr("Copy the selected lines, or all lines, to the clipboard"));
  connect(clear_, &QPushButton::clicked, this, &LogPanel::clear);
  connect(copy_, &QPushButton::clicked, this, &LogPanel::copyToClipboard);
  auto* copyShortcut = new QShortcut(QKeySequence::Copy, list_, nullptr, nullptr, Qt::WidgetShortcut);
  connect(copyShortcut, &QShortcut::activated, this, &LogPanel::copyToClipboard);

  auto* buttons = new QHBoxLayout;
  buttons->setContentsMargins(0, 0, 0, 0);
  buttons->addWidget(badge_);
  buttons->addStretch(1);
  buttons->addWidget(copy_);
  buttons->addWidget(clear_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->setSpacing(4);
  layout->addWidget(list_, 1);
  layout->addLayout(buttons);
}

int LogPanel::lineCount() const {
  return list_->count();
}

QString LogPanel::badgeText() const {
  if (errors_ == 0) return {};
  return errors_ == 1 ? tr("1 error") : tr("%1 errors").arg(errors_);
}

QString LogPanel::lineText(int row) const {
  const QListWidgetItem* item = list_->item(row);
  return item ? item->text() : QString();
}

QColor LogPanel::lineColor(int row) const {
  const QListWidgetItem* item = list_->item(row);
  return item ? item->foreground().color() : QColor();
}

QString LogPanel::text() const {
  QStringList lines;
  for (int i = 0; i < list_->count(); ++i) lines << list_->item(i)->text();
  return lines.join('\n');
}

void LogPanel::appendMessage(const QString& level, const QString& text) {
  const Level l = levelOf(level);
  const QString tag = l == Level::Error ? tr("error") : l == Level::Warning ? tr("warning") : tr("info");
  const QString stamp = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
  // Multi-line messages stay one entry (a compiler log, a stack of causes).
  QString oneLine = text;
  oneLine.replace('\n', QStringLiteral(" ⏎ "));
  auto* item = new QListWidgetItem(QStringLiteral("%1  %2  %3").arg(stamp, tag.leftJustified(7), oneLine));
  item->setForeground(colorOf(l, palette()));
  item->setData(kLevelRole, static_cast<int>(l));
  item->setToolTip(text);
  const QScrollBar* bar = list_->verticalScrollBar();
  const bool atBottom = bar->value() >= bar->maximum();  // follow new lines unless the user scrolled up
  const int errorsBefore = errors_;
  list_->addItem(item);
  if (l == Level::Warning) ++warnings_;
  if (l == Level::Error) ++errors_;
  while (list_->count() > kMaxLines) {
    std::unique_ptr<QListWidgetItem> old(list_->takeItem(0));
    const auto oldLevel = static_cast<Level>(old->data(kLevelRole).toInt());
    if (oldLevel == Level::Error) --errors_;
    if (oldLevel == Level::Warning) --warnings_;
  }
  if (atBottom) list_->scrollToBottom();
  if (errors_ != errorsBefore) {
    emit errorCountChanged(errors_);
    updateBadge();
  }
}

void LogPanel::clear() {
  list_->clear();
  const bool hadErrors = errors_ > 0;
  errors_ = warnings_ = 0;
  if (hadErrors) emit errorCountChanged(0);
  updateBadge();
}

void LogPanel::copyToClipboard() const {
  QStringList lines;
  for (int i = 0; i < list_->count(); ++i)
    if (list_->item(i)->isSelected()) lines << list_->item(i)->text();
  QApplication::clipboard()->setText(lines.isEmpty() ? text() : lines.join('\n'));
}

void LogPanel::updateBadge() {
  const QString text = badgeText();
  badge_->setText(text);
  badge_->setVisible(!text.isEmpty());
  emit badgeTextChanged(text);
}

}  // namespace kerf
