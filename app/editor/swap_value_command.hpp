#pragma once
// One undo step that swaps a value between what it was before an edit and what the edit made it: undo
// applies the old value, redo the new one, both through a setter (a Document's apply… function) that
// changes the value without pushing a command. Every snapshot command of the editor is one of these
// (document_commands.hpp, log_commands.hpp).
#include <QUndoCommand>
#include <functional>
#include <utility>

namespace kerf {

// How a SwapValueCommand joins the stack. A drag merges (tiled's ChangeValue pattern): a command with a
// merge id stays open until one with finished = true arrives, the commands of the same id in between
// merging into it.
struct SwapMerge {
  int id = -1;  // QUndoCommand::id(); -1 never merges
  bool finished = true;
};

// Whether an edit that ends where it started (before == after, also after merging) is kept as a step or
// is obsolete and leaves none. Part of the type: only a value with == can be dropped.
enum class Unchanged { Kept, Dropped };

template <typename T, Unchanged IfUnchanged = Unchanged::Kept>
class SwapValueCommand : public QUndoCommand {
 public:
  using Setter = std::function<void(const T&)>;

  SwapValueCommand(Setter apply, T before, T after, const QString& text, SwapMerge merge = {})
      : apply_(std::move(apply)), before_(std::move(before)), after_(std::move(after)), merge_(merge) {
    setText(text);
    updateObsolete();
  }

  void undo() override { apply_(before_); }
  void redo() override { apply_(after_); }
  int id() const override { return merge_.id; }

  // The stack asks only for a command of the same id, so of the same kind.
  bool mergeWith(const QUndoCommand* other) override {
    if (merge_.finished) return false;
    const auto* next = static_cast<const SwapValueCommand*>(other);
    after_ = next->after_;
    merge_.finished = next->merge_.finished;
    updateObsolete();
    return true;
  }

  const T& before() const { return before_; }
  const T& after() const { return after_; }

 private:
  void updateObsolete() {
    if constexpr (IfUnchanged == Unchanged::Dropped) setObsolete(before_ == after_);
  }

  Setter apply_;
  T before_, after_;
  SwapMerge merge_;
};

}  // namespace kerf
