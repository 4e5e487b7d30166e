#pragma once
// A picture of a surface of the block made off the view, with where its pixels lie in the block: the
// photo-true appearance (issue 17) of a face or a cut, handed to the 3D view and the cut panel. A view
// shows it instead of its own rendering only while it shows the model (and, for a cut, the plane) the
// picture was made for, so a stale picture never covers a newer model; it shows its own rendering in
// the meantime (procedural first, the photo-true surface replacing it as it lands).
#include <QImage>
#include <glm/vec2.hpp>
#include <memory>

#include "appearance/surface_grid.hpp"
#include "geometry/cut_plane.hpp"

namespace kerf {

class WoodModel;

struct SurfaceImage {
  QImage image;
  SurfaceGrid grid;  // pixel (x, y)'s centre is grid.point(x, y), block mm

  // The texture coordinates (0..1, t counted from the image's first row, as QOpenGLTexture uploads it)
  // of a block point on the surface.
  glm::vec2 textureCoordinates(glm::vec3 blockPoint) const;
};

// A cut's picture and what it was made for.
struct CutAppearance {
  std::shared_ptr<const WoodModel> model;
  CutPlaneSetting plane;
  SurfaceImage surface;
};

}  // namespace kerf
