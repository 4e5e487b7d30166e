#pragma once
// The editor's log, for a dock: timestamped info / warning / error lines, colour-coded, newest last.
// Connect JobRunner::message (or anything with the same signature) to appendMessage(). The badge
// text ("2 errors") is for the dock's title or a status-bar button; Clear empties the log and resets it.
#include <QDateTime>
#include <QString>
#include <QWidget>

class QLabel;
class QListWidget;
class QPushButton;

namespace kerf {

class LogPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LogPanel(QWidget* parent = nullptr);

  int lineCount() const;
  int errorCount() const { return errors_; }
  int warningCount() const { return warnings_; }
  QString badgeText() const;  // "" without errors, else "1 error" / "3 errors"
  QString text() const;       // every line, as copied
  QString lineText(int row) const;
  QColor lineColor(int row) const;

  static constexpr int kMaxLines = 5000;  // the oldest lines go first

 public slots:
  // level: "info", "warning" or "error" (anything else counts as info).
  void appendMessage(const QString& level, const QString& text);
  void clear();
  // The selected lines, or all lines when none is selected.
  void copyToClipboard() const;

 signals:
  void errorCountChanged(int errors);
  void badgeTextChanged(const QString& text);

 private:
  void updateBadge();

  QListWidget* list_;
  QLabel* badge_;
  QPushButton* clear_;
  QPushButton* copy_;
  int errors_ = 0, warnings_ = 0;
};

}  // namespace kerf
