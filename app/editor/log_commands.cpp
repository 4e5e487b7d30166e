#include "log_commands.hpp"

#include "document.hpp"

namespace kerf {

bool operator==(const Board& a, const Board& b) {
  return a.center == b.center && a.size == b.size && a.rotationDeg == b.rotationDeg;
}

SetLogCommand::SetLogCommand(Document* document, std::optional<ProjectLog> before, Block beforeBlock,
                             std::optional<ProjectLog> after, Block afterBlock, const QString& text)
    : document_(document),
      before_(std::move(before)),
      after_(std::move(after)),
      beforeBlock_(beforeBlock),
      afterBlock_(afterBlock) {
  setText(text);
}

void SetLogCommand::undo() {
  document_->applyLog(before_, beforeBlock_);
}
void SetLogCommand::redo() {
  document_->applyLog(after_, afterBlock_);
}

SetBoardCommand::SetBoardCommand(Document* document, const Board& before, const Board& after, bool finished)
    : document_(document), before_(before), after_(after), finished_(finished) {
  setText(QObject::tr("Move board"));
  setObsolete(before == after);
}

void SetBoardCommand::undo() {
  document_->applyBoard(before_);
}
void SetBoardCommand::redo() {
  document_->applyBoard(after_);
}

bool SetBoardCommand::mergeWith(const QUndoCommand* other) {
  if (finished_) return false;
  const auto* next = static_cast<const SetBoardCommand*>(other);
  after_ = next->after_;
  finished_ = next->finished_;
  setObsolete(after_ == before_);  // dragged back to where it started
  return true;
}

SetKnotsCommand::SetKnotsCommand(Document* document, std::vector<Knot> before, std::vector<Knot> after,
                                 const QString& text)
    : document_(document), before_(std::move(before)), after_(std::move(after)) {
  setText(text);
}

void SetKnotsCommand::undo() {
  document_->applyKnots(before_);
}
void SetKnotsCommand::redo() {
  document_->applyKnots(after_);
}

}  // namespace kerf
