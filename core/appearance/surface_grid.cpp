#include "appearance/surface_grid.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {

float SurfaceGrid::pxPerMm() const {
  return 1.0f / glm::length(right);
}

SurfaceGrid faceGrid(const Block& block, FaceId face, glm::ivec2 size) {
  const FaceFrame frame = block.face(face);
  SurfaceGrid grid;
  grid.width = size.x;
  grid.height = size.y;
  grid.right = frame.right * (frame.widthMm / size.x);
  grid.down = frame.down * (frame.heightMm / size.y);
  grid.origin = block.imageToBlock(face, {0.5f, 0.5f}, size);
  grid.normal = frame.normal;
  return grid;
}

SurfaceGrid cutGrid(const Block& block, const CutPlane& plane, float pxPerMm) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  const auto bounds = plane.boundsInBlock(block);
  if (!bounds) throw InputError("the cut plane does not pass through the block");
  const glm::vec2 extent = bounds->max - bounds->min;
  SurfaceGrid grid;
  // As renderCut: image right = plane right, image down = plane -up, top-left at (min.x, max.y).
  grid.width = pixelsAlong(std::ceil(double(extent.x) * pxPerMm - 1e-3));
  grid.height = pixelsAlong(std::ceil(double(extent.y) * pxPerMm - 1e-3));
  checkImageSize({grid.width, grid.height}, "the image of the cut", pxPerMm);
  grid.right = plane.right() / pxPerMm;
  grid.down = -plane.up() / pxPerMm;
  grid.origin = plane.toBlock({bounds->min.x + 0.5f / pxPerMm, bounds->max.y - 0.5f / pxPerMm});
  grid.normal = plane.normal();
  return grid;
}

}  // namespace kerf
