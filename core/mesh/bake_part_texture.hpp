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

}  // namespace kerf
