#pragma once
// Undo commands of the log and its board (docs/editor.md, "Logs and boards"). Like the parameter and
// cut-plane commands, a board being dragged merges into one step until an edit with finished = true.
#include <QUndoCommand>
#include <optional>
#include <vector>

#include "geometry/block.hpp"
#include "io/project_log.hpp"

namespace kerf {

class Document;

// Ids for mergeable log commands (document_commands.hpp uses 1 and 1000 + parameter).
enum LogCommandId { kBoardCommand = 900 };

// A log attached to, replaced in or removed from the document, with the block it sets (the board's size).
class SetLogCommand : public QUndoCommand {
 public:
  SetLogCommand(Document* document, std::optional<ProjectLog> before, Block beforeBlock,
                std::optional<ProjectLog> after, Block afterBlock, const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  std::optional<ProjectLog> before_, after_;
  Block beforeBlock_, afterBlock_;
};

// The board's placement and size in the log.
class SetBoardCommand : public QUndoCommand {
 public:
  SetBoardCommand(Document* document, const Board& before, const Board& after, bool finished);
  void undo() override;
  void redo() override;
  int id() const override { return kBoardCommand; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  Document* document_;
  Board before_, after_;
  bool finished_;
};

// The log's knots before and after one edit (added, deleted or changed).
class SetKnotsCommand : public QUndoCommand {
 public:
  SetKnotsCommand(Document* document, std::vector<Knot> before, std::vector<Knot> after, const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  std::vector<Knot> before_, after_;
};

bool operator==(const Board& a, const Board& b);

}  // namespace kerf
