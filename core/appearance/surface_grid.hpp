#pragma once
// A surface to give an appearance to, as a regular grid of points in the block: a block face or a cut
// plane, sampled at some pixels per mm. The photo-true appearance computes its guidance features on such
// grids, for the photos (the faces at the photos' own pixel grid) and for the surfaces it synthesises.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"

namespace kerf {

struct SurfaceGrid {
  int width = 0, height = 0;
  glm::vec3 origin{0.0f};  // block mm of the centre of pixel (0, 0)
  glm::vec3 right{0.0f};   // block mm from a pixel to its right neighbour
  glm::vec3 down{0.0f};    // block mm from a pixel to the one below it
  glm::vec3 normal{0.0f};  // unit, the side the surface is seen from

  glm::vec3 point(float x, float y) const { return origin + x * right + y * down; }
  float pxPerMm() const;
};

// Face `face` on an image of `size` pixels (the grid of renderFace and of the face photos).
SurfaceGrid faceGrid(const Block& block, FaceId face, glm::ivec2 size);

// The cut on `plane` at pxPerMm: the same image rectangle as renderCut (the bounds of the plane's
// polygon in the block; InputError when the plane misses the block).
SurfaceGrid cutGrid(const Block& block, const CutPlane& plane, float pxPerMm);

}  // namespace kerf
