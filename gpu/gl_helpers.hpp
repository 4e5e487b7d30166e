#pragma once
// Small conversions every OpenGL user in widgets/ needs.
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QVector3D>
#include <glm/vec3.hpp>

namespace kerf {

inline QVector3D toQt(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

// The OpenGL 3.3 functions of the current context (callers make a context current first).
inline QOpenGLExtraFunctions* currentGl() {
  return QOpenGLContext::currentContext()->extraFunctions();
}

// Tightly packed rows (GL_UNPACK_ALIGNMENT 1) while it lives, then the alignment as it was. QPainter's
// OpenGL engine uploads its glyphs with the default alignment and does not set it itself: text drawn
// after a table upload that left it at 1 came out garbled.
class PackedRowsUpload {
 public:
  PackedRowsUpload() {
    currentGl()->glGetIntegerv(GL_UNPACK_ALIGNMENT, &previous_);
    currentGl()->glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  ~PackedRowsUpload() { currentGl()->glPixelStorei(GL_UNPACK_ALIGNMENT, previous_); }
  PackedRowsUpload(const PackedRowsUpload&) = delete;
  PackedRowsUpload& operator=(const PackedRowsUpload&) = delete;

 private:
  GLint previous_ = 4;
};

}  // namespace kerf
