#include "editor_controller.hpp"

#include <QWidget>

namespace kerf {

EditorController::EditorController(const EditorContext& context)
    : QObject(context.window), window_(context.window), document_(context.document), jobs_(context.jobs) {}

void EditorController::showError(const QString& message) {
  emit logged("error", message);
  emit alerted(message, message);
}

}  // namespace kerf
