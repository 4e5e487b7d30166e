#include "log_commands.hpp"

#include "document.hpp"

namespace kerf {

bool operator==(const Board& a, const Board& b) {
  return a.center == b.center && a.size == b.size && a.rotationDeg == b.rotationDeg;
}

QUndoCommand* setLogCommand(Document* document, LogAndBlockValue before, LogAndBlockValue after,
                            const QString& text) {
  return new SwapValueCommand<LogAndBlockValue>(
      [document](const LogAndBlockValue& value) { document->applyLog(value.log, value.block); },
      std::move(before), std::move(after), text);
}

QUndoCommand* setBoardCommand(Document* document, const Board& before, const Board& after, bool finished) {
  return new SwapValueCommand<Board, Unchanged::Dropped>(
      [document](const Board& board) { document->applyBoard(board); }, before, after,
      QObject::tr("Move board"), {kBoardCommand, finished});
}

QUndoCommand* setKnotsCommand(Document* document, std::vector<Knot> before, std::vector<Knot> after,
                              const QString& text) {
  return new SwapValueCommand<std::vector<Knot>>(
      [document](const std::vector<Knot>& knots) { document->applyKnots(knots); }, std::move(before),
      std::move(after), text);
}

}  // namespace kerf
