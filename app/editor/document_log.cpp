// Document: the log and the board cut from it (docs/editor.md, "Logs and boards"). The document's block
// follows the board's size, so the faces view, the 3D view and the cut show the board.
#include "document.hpp"
#include "log_commands.hpp"
#include "util/error.hpp"

namespace kerf {

void Document::setLog(std::optional<ProjectLog> log, const QString& undoText) {
  if (log) validate(log->log);
  const Block after = log ? Block(log->board.size) : project_.block;
  undo_.push(setLogCommand(this, {project_.log, project_.block}, {std::move(log), after}, undoText));
}

void Document::editBoard(const Board& board, bool finished) {
  if (!project_.log) return;
  const Block checked(board.size);  // InputError unless every side is finite and positive
  undo_.push(setBoardCommand(this, project_.log->board, board, finished));
}

void Document::editKnots(std::vector<Knot> knots, const QString& undoText) {
  if (!project_.log) return;
  LogModel candidate = project_.log->log;  // refuse a bad knot before it reaches the undo stack
  candidate.knots = knots;
  validate(candidate);
  undo_.push(setKnotsCommand(this, project_.log->log.knots, std::move(knots), undoText));
}

void Document::applyLog(const std::optional<ProjectLog>& log, const Block& block) {
  project_.log = log;
  const bool resized = block.size() != project_.block.size();
  project_.block = block;
  if (resized) {
    rebuildModel();
    emit blockChanged();
  }
  emit logChanged();
  emit modelChanged();
}

void Document::applyBoard(const Board& board) {
  if (!project_.log) return;
  project_.log->board = board;
  const bool resized = board.size != project_.block.size();
  if (resized) {
    project_.block = Block(board.size);
    rebuildModel();
    emit blockChanged();
  }
  emit boardChanged();
  if (resized) emit modelChanged();
}

void Document::applyKnots(const std::vector<Knot>& knots) {
  if (!project_.log) return;
  project_.log->log.knots = knots;
  emit logChanged();
}

}  // namespace kerf
