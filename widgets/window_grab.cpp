#include "window_grab.hpp"

#include <QOpenGLWidget>
#include <QPainter>
#include <QPixmap>
#include <QWidget>

namespace kerf {

QImage grabWindowWithGl(QWidget* window) {
  QImage image = window->grab().toImage();
  QPainter painter(&image);
  const qreal scale = image.width() / qreal(std::max(1, window->width()));
  for (QOpenGLWidget* view : window->findChildren<QOpenGLWidget*>()) {
    if (!view->isVisible()) continue;
    const QPoint at = view->mapTo(window, QPoint(0, 0));
    painter.drawImage(QRectF(at * scale, view->size() * scale), view->grabFramebuffer());
  }
  return image;
}

}  // namespace kerf
