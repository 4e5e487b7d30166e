#pragma once
// What the GPU parity tests share: an offscreen OpenGL 3.3 context and the GPU renderer under test.
#include <QtDebug>
#include <exception>
#include <memory>
#include <string>

#include "gpu/offscreen_gl_context.hpp"

namespace kerf::testing {

template <class Renderer>
class GlRendererFixture {
 protected:
  // Makes the context current and creates the renderer (compiling its shaders); returns why that
  // failed, or an empty string.
  std::string startRenderer() {
    if (std::string error = gl_.makeCurrent(); !error.empty()) return error;
    qInfo() << "OpenGL renderer:" << gl_.renderer().c_str();
    try {
      renderer_ = std::make_unique<Renderer>();
    } catch (const std::exception& e) {
      return e.what();
    }
    return {};
  }
  void stopRenderer() {
    renderer_.reset();  // while its context is still current
    gl_.doneCurrent();
  }

  std::unique_ptr<Renderer> renderer_;

 private:
  OffscreenGlContext gl_;
};

}  // namespace kerf::testing
