#include "gpu/offscreen_gl_context.hpp"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace kerf {

OffscreenGlContext::OffscreenGlContext() = default;
OffscreenGlContext::~OffscreenGlContext() = default;

std::string OffscreenGlContext::makeCurrent() {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  context_ = std::make_unique<QOpenGLContext>();
  context_->setFormat(format);
  surface_ = std::make_unique<QOffscreenSurface>();
  surface_->setFormat(format);
  surface_->create();
  if (!context_->create() || !context_->makeCurrent(surface_.get()))
    return "cannot create an OpenGL 3.3 core context (run under xvfb-run with Mesa)";
  const auto version = context_->format().version();
  if (version < qMakePair(3, 3)) {
    return "the OpenGL context is version " + std::to_string(version.first) + "." +
           std::to_string(version.second) + ", 3.3 is needed";
  }
  return {};
}

std::string OffscreenGlContext::renderer() const {
  if (!context_) return {};
  return reinterpret_cast<const char*>(context_->functions()->glGetString(GL_RENDERER));
}

void OffscreenGlContext::doneCurrent() {
  if (context_) context_->doneCurrent();
}

}  // namespace kerf
