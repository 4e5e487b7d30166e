#pragma once
// Undo commands of the log and its board (docs/editor.md, "Logs and boards"), each a SwapValueCommand.
// Like the parameter and cut-plane commands, a board being dragged merges into one step until an edit
// with finished = true.
#include <QUndoCommand>
#include <optional>
#include <vector>

#include "geometry/block.hpp"
#include "io/project_log.hpp"
#include "swap_value_command.hpp"

namespace kerf {

class Document;

// Ids for mergeable log commands (document_commands.hpp uses 1 and 1000 + parameter).
enum LogCommandId { kBoardCommand = 900 };

// A log attached to, replaced in or removed from the document, with the block it sets (the board's size).
struct LogAndBlockValue {
  std::optional<ProjectLog> log;
  Block block;
};

QUndoCommand* setLogCommand(Document* document, LogAndBlockValue before, LogAndBlockValue after,
                            const QString& text);
// The board's placement and size in the log.
QUndoCommand* setBoardCommand(Document* document, const Board& before, const Board& after, bool finished);
// The log's knots before and after one edit (added, deleted or changed).
QUndoCommand* setKnotsCommand(Document* document, std::vector<Knot> before, std::vector<Knot> after,
                              const QString& text);

bool operator==(const Board& a, const Board& b);

}  // namespace kerf
