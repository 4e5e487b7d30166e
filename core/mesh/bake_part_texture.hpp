#pragma once
// Baking the block's wood onto a part's atlas (issue 7): each texel covered by a triangle gets the wood
// colour of the model at that texel's 3D point, found through the triangle's barycentric coordinates in
// block mm: the mean of samples x samples points spread evenly over the texel (1: its centre), as the
// image exports supersample their pixels. Texels whose square touches a triangle but whose
// centre lies just outside it (the chart's rim) are evaluated on the triangle's plane continued, so
// bilinear filtering at the rim blends real wood. The remaining gutter is filled outwards from the
// charts (each empty texel takes the mean of its filled neighbours, padding + 1 rounds), and what stays
// empty gets the mean colour, so mipmaps do not bleed black into the part.
#include <cstddef>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "io/image.hpp"
#include "mesh/uv_atlas.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;

struct BakedTexture {
  Image image;              // RGB, 0..1 sRGB-encoded as the face images, atlas.resolution square
  std::size_t samples = 0;  // model evaluations (texels on the part)
  std::vector<int> owner;   // per texel: the triangle it was evaluated on, -1 for the gutter
};

// Multithreaded over rows (util/parallel.hpp); throws Cancelled.
// samples: per texel side, 1..8. Throws InputError for other counts.
BakedTexture bakePartTexture(const WoodModel& model, const UvAtlas& atlas, int samples = 1,
                             const Progress& progress = {});

// The same bake with colours from elsewhere (the photo-true appearance, export/photo_true_part_bake.hpp):
// the colour at a point of triangle `triangle` given by its barycentric coordinates (which may be slightly
// negative at the rim). Called from worker threads.
using AtlasColour = std::function<glm::vec3(int triangle, glm::vec3 barycentric)>;
BakedTexture bakeAtlasTexture(const UvAtlas& atlas, const AtlasColour& colourAt, int samples = 1,
                              const Progress& progress = {});

// The triangle each texel is evaluated on (-1: the gutter), as the bake marks them.
std::vector<int> atlasTexelOwners(const UvAtlas& atlas);
// Barycentric coordinates in triangle `triangle` of a point in texel units ((0.5, 0.5): the centre of the
// top-left texel); negative outside the triangle.
glm::vec3 atlasBarycentric(const UvAtlas& atlas, int triangle, glm::vec2 texelPoint);

}  // namespace kerf
