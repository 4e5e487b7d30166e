#pragma once
// A screenshot of a window including its OpenGL views with their painted overlays (rulers, handles).
// QWidget::grab() takes each QOpenGLWidget's last frame without what QPainter drew over it, so the GL
// views are grabbed on their own (grabFramebuffer) and painted over the window's picture.
#include <QImage>

class QWidget;

namespace kerf {

QImage grabWindowWithGl(QWidget* window);

}  // namespace kerf
