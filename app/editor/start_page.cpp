#include "start_page.hpp"

#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "recent_files.hpp"

namespace kerf {

StartPage::StartPage(RecentFiles* recent, QWidget* parent) : QWidget(parent), recent_(recent) {
  setObjectName(QStringLiteral("startPage"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(24, 24, 24, 24);
  layout->setSpacing(10);
  auto* title = new QLabel(tr("<h2>Start with the wood</h2>"), this);
  layout->addWidget(title);
  const auto button = [this, layout](const QString& text, const QString& tip) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    b->setMinimumHeight(32);
    b->setStyleSheet(QStringLiteral("text-align: left; padding: 4px 12px;"));
    layout->addWidget(b);
    return b;
  };
  photos_ =
      button(tr("Open Photos of a Block…"),
             tr("A folder holding a photo of each face of the block, named A_col.png .. F_col.png (any of "
                "them may be missing). Photos named otherwise: File ▸ Import Photos."));
  project_ = button(tr("Open Project…"), tr("A Kerf project (.kerf) you saved before"));
  demo_ = button(tr("Open the Demo Block"),
                 tr("A 40 mm block of a made-up wood, with photos of its six faces, to try Kerf on"));
  auto* next = new QLabel(
      tr("With the photos open, <b>Reconstruct</b> (Ctrl+R) finds the rings on each face, fits the growth "
         "of the tree through the block, then the look of the wood, and shows a cut."),
      this);
  next->setWordWrap(true);
  layout->addWidget(next);
  layout->addSpacing(8);
  layout->addWidget(new QLabel(tr("<b>Recent</b>"), this));
  recentList_ = new QListWidget(this);
  recentList_->setObjectName(QStringLiteral("recentList"));
  recentList_->setToolTip(tr("Double-click to open"));
  layout->addWidget(recentList_, 1);

  connect(photos_, &QPushButton::clicked, this, &StartPage::openPhotosRequested);
  connect(project_, &QPushButton::clicked, this, &StartPage::openProjectRequested);
  connect(demo_, &QPushButton::clicked, this, &StartPage::demoRequested);
  connect(recentList_, &QListWidget::itemActivated, this,
          [this](QListWidgetItem* item) { emit recentRequested(item->data(Qt::UserRole).toString()); });
  connect(recent_, &RecentFiles::listChanged, this, &StartPage::refresh);
  refresh();
}

void StartPage::refresh() {
  recentList_->clear();
  for (const QString& path : recent_->files()) {
    if (!QFileInfo::exists(path)) continue;
    auto* item =
        new QListWidgetItem(QFileInfo(path).fileName() + QStringLiteral("  —  ") + path, recentList_);
    item->setData(Qt::UserRole, path);
    item->setToolTip(path);
  }
  if (recentList_->count() == 0) {
    auto* none = new QListWidgetItem(tr("Nothing opened yet"), recentList_);
    none->setFlags(Qt::NoItemFlags);
  }
}

}  // namespace kerf
