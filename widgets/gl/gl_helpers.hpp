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

}  // namespace kerf
