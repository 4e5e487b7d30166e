#pragma once
// What the editor's knot tables share (docs/editor.md): one row per knot, whole rows selected, headers
// that say in wood terms what each column is, a Dead box and a Died-at column, a Delete Knot button (and
// the Del key while the table has the focus), an optional Add Knot button, and a refused value shown as a
// tooltip at its cell. The log's table (knot_table.hpp) and the block's (block_knot_table.hpp) fill the
// rows and turn an edited cell into a knot; filling the rows never reports an edit.
#include <QString>
#include <QStringList>
#include <QWidget>

class QPushButton;
class QTableWidget;

namespace kerf {

class KnotTableBase : public QWidget {
  Q_OBJECT

 public:
  struct Column {  // a header and its tooltip
    QString header;
    QString tip;
  };

  int selectedKnot() const;  // -1: none
  void setSelectedKnot(int knot);
  QTableWidget* table() const { return table_; }
  // The last refusal (tests), shown at its cell until the next edit.
  QString lastRefusal() const { return lastRefusal_; }

 signals:
  void addRequested();
  void deleteRequested(int knot);
  void knotSelected(int knot);
  // A typed value was refused (also shown at its cell): why, in words for the status bar.
  void valueRefused(const QString& why);

 protected:
  // `addTip` empty: no Add Knot button.
  KnotTableBase(const QList<Column>& columns, const QString& addTip, const QString& deleteTip,
                QWidget* parent);

  // Fills `count` rows: between beginRows and endRows no cell edit is reported; endRows selects the row
  // that was selected before again.
  void beginRows(int count);
  void endRows();
  bool filling() const { return updating_; }
  void setNumber(int row, int column, double value, int decimals = 2, const QString& tip = {});
  void setText(int row, int column, const QString& text, const QString& tip = {});  // read-only
  // The Dead box and the Died-at cell (editable while dead, "—" while alive).
  void setDeath(int row, int deadColumn, int deathColumn, double death, const QString& tip = {});
  bool isChecked(int row, int column) const;
  double number(int row, int column) const;
  // Says why a value is refused, at its cell; the row is filled again by the caller.
  void refuse(int row, int column, const QString& why);

  virtual void cellEdited(int row, int column) = 0;

 private:
  QTableWidget* table_ = nullptr;
  QPushButton* delete_ = nullptr;
  bool updating_ = false;
  int selectedBefore_ = -1;
  QString lastRefusal_;
};

}  // namespace kerf
