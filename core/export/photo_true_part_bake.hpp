#pragma once
// A textured part in the photo-true appearance (issue 17): the part's surface made of the block's own
// photos, re-grown along the fitted field, baked onto the part's texture atlas.
//
// The synthesis works at the photos' pixels per mm (their patches are copied pixel for pixel), so it runs
// on an atlas of its own at that scale (the same charts, mesh/uv_atlas.hpp with maxTexelsPerMm), and the
// result is resampled onto the part's atlas through each triangle (the bake's supersampling averages it
// when the part's texture is coarser). Each texel of the synthesis atlas has its own point in the block
// and its own frame (the triangle's steps in 3D per texel right and down), so the guidance is that of the
// true surface (appearance/texel_guidance.hpp); the charts are separate regions. Each large chart's
// rectangle is synthesised on its own (the atlas' empty space is not), the small charts together.
//
// Seams: each chart is synthesised as an island of the atlas. Where two charts meet on the part (a box's
// edge, or the border between two charts of a curved surface) the rings, the heart/sap boundary and the
// grain run on as the field says, but single pores and rays do not continue: the same as where two
// exported faces meet. A chart tilted against its projection axis is stretched up to 1.7 times across
// the tilt (the atlas' foreshortening), and so are the photo patches on it.
#include "mesh/bake_part_texture.hpp"
#include "mesh/uv_atlas.hpp"
#include "util/progress.hpp"

namespace kerf {

class PhotoTrueAppearance;
class WoodModel;

// `atlas` is the part's (any resolution); samples: per texel side, as bakePartTexture. InputError when
// the part needs an atlas larger than 16384 texels square at the photos' resolution. Cancellable.
BakedTexture bakePhotoTruePart(const PhotoTrueAppearance& appearance, const WoodModel& model,
                               const Mesh& placedMesh, const UvAtlas& atlas, int samples,
                               const Progress& progress = {});

}  // namespace kerf
