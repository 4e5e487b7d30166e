// SwapValueCommand (app/editor/swap_value_command.hpp), the one undo command behind every snapshot
// command of the editor: undo and redo swap the value through its setter, drags merge into one step, and an
// edit that ends where it started leaves none.
#include <QUndoStack>
#include <QtTest>
#include <vector>

#include "swap_value_command.hpp"

using namespace kerf;

namespace {

constexpr int kMergeId = 42;

// A value that cannot be compared: the command must still work (it keeps every step).
struct Opaque {
  int value = 0;
};

using DragCommand = SwapValueCommand<int, Unchanged::Dropped>;

}  // namespace

class SwapValueCommandTest : public QObject {
  Q_OBJECT

 private slots:
  void undoAndRedoSwapTheValue() {
    int value = 1;
    QUndoStack stack;
    std::vector<int> applied;
    const auto set = [&](const int& v) {
      value = v;
      applied.push_back(v);
    };
    stack.push(new SwapValueCommand<int>(set, value, 2, "Set to 2"));
    QCOMPARE(value, 2);  // push redoes
    QCOMPARE(stack.undoText(), QString("Set to 2"));
    stack.undo();
    QCOMPARE(value, 1);
    stack.redo();
    QCOMPARE(value, 2);
    QCOMPARE(applied, (std::vector<int>{2, 1, 2}));
  }

  void aDragMergesIntoOneStepUntilFinished() {
    int value = 0;
    QUndoStack stack;
    const auto set = [&](const int& v) { value = v; };
    const auto edit = [&](int after, bool finished) {
      stack.push(new DragCommand(set, value, after, "Drag", {kMergeId, finished}));
    };
    edit(1, false);
    edit(2, false);
    edit(3, true);
    QCOMPARE(stack.count(), 1);
    edit(4, true);  // the drag had finished: a step of its own
    QCOMPARE(stack.count(), 2);
    stack.undo();
    stack.undo();
    QCOMPARE(value, 0);
    stack.redo();
    QCOMPARE(value, 3);
  }

  void aDragBackToTheStartLeavesNoStep() {
    int value = 5;
    QUndoStack stack;
    const auto set = [&](const int& v) { value = v; };
    stack.push(new DragCommand(set, 5, 6, "Drag", {kMergeId, false}));
    stack.push(new DragCommand(set, 6, 5, "Drag", {kMergeId, true}));
    QCOMPARE(stack.count(), 0);
    QCOMPARE(value, 5);
    stack.push(new DragCommand(set, 5, 5, "No change"));
    QCOMPARE(stack.count(), 0);
  }

  void keptUnchangedEditsAreSteps() {
    int value = 0;
    QUndoStack stack;
    const auto set = [&](const int& v) { value = v; };
    stack.push(new SwapValueCommand<int>(set, 0, 0, "Same value, kept"));
    stack.push(new SwapValueCommand<int>(set, 0, 1, "One"));
    QCOMPARE(stack.count(), 2);
  }

  void valuesWithoutEqualityWork() {
    Opaque value{1};
    QUndoStack stack;
    stack.push(new SwapValueCommand<Opaque>([&](const Opaque& v) { value = v; }, value, Opaque{2}, "Opaque"));
    QCOMPARE(stack.count(), 1);
    stack.undo();
    QCOMPARE(value.value, 1);
  }
};

QTEST_MAIN(SwapValueCommandTest)
#include "test_swap_value_command.moc"
