#pragma once
// Guidance features (appearance/guidance_features.hpp) on a surface that is not one plane: the texels of
// an image (a part's texture atlas), each with its own point in the block and its own steps to its right
// and lower neighbours on the surface (the texel's tangent frame, from the UV mapping), grouped in regions
// (the atlas' charts) that are separate pieces of surface. The features are those of computeGuidance,
// with the growth gradient taken in 3D at each texel (neighbouring texels may lie on another triangle or
// in another chart) and the directions in the image found through each texel's own frame, which need not
// be orthogonal nor of equal lengths (a chart projected along an axis is stretched where the surface is
// tilted against it). The grain direction is averaged over about a millimetre within a region only.
// Texels of no region (the gutter between charts) copy the features of the nearest texel of a region, so
// that patches reaching over a chart's edge see the chart continued; their `inside` is 0.
#include <glm/vec3.hpp>
#include <vector>

#include "appearance/guidance_features.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;

struct TexelSurface {
  int width = 0, height = 0;
  std::vector<glm::vec3> point;        // block mm of each texel's centre
  std::vector<glm::vec3> right, down;  // block mm from a texel to its right / lower neighbour
  std::vector<int> region;             // the piece of surface a texel lies on; -1: none
};

// Rows in parallel; cancellable. InputError when the vectors' sizes differ from width x height.
SurfaceGuidance computeTexelGuidance(const WoodModel& model, const TexelSurface& surface,
                                     const GuidanceWeights& weights, const Progress& progress = {});

}  // namespace kerf
