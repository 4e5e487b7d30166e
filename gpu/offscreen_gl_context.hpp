#pragma once
// An OpenGL 3.3 core context current on an offscreen surface: what headless GPU rendering (kerf-cli
// --gpu, the parity tests, the GPU benchmarks) draws with. Needs a QGuiApplication.
#include <memory>
#include <string>

class QOpenGLContext;
class QOffscreenSurface;

namespace kerf {

class OffscreenGlContext {
 public:
  OffscreenGlContext();
  ~OffscreenGlContext();
  OffscreenGlContext(const OffscreenGlContext&) = delete;
  OffscreenGlContext& operator=(const OffscreenGlContext&) = delete;

  // Creates the context and makes it current; returns why that failed, or an empty string.
  std::string makeCurrent();
  std::string renderer() const;  // GL_RENDERER of the current context
  void doneCurrent();

 private:
  std::unique_ptr<QOpenGLContext> context_;
  std::unique_ptr<QOffscreenSurface> surface_;
};

}  // namespace kerf
