#pragma once
// Every OpenGL view of Kerf (3D block, cut panel) uses one format: OpenGL 3.3 core. Call before the
// QApplication is created, so all contexts match and can share.
#include <QSurfaceFormat>

namespace kerf {

inline void useKerfSurfaceFormat() {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace kerf
