#pragma once
// CPU renderers of the wood model: block faces (for comparing with photos) and arbitrary cuts.
// Rows are spread over the worker threads (util/parallel.hpp); both are cancellable.
#include <array>

#include "geometry/cut_plane.hpp"
#include "image/image.hpp"
#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

// Face `face` at `size` pixels (RGB). `samples` x `samples` points per pixel are averaged (1 = the
// pixel centre only), which is what a camera sensor does and keeps pores from aliasing.
Image renderFace(const WoodModel& model, FaceId face, glm::ivec2 size, int samples = 1,
                 const Progress& progress = {});

// All six faces at pxPerMm, in A..F order.
std::array<Image, 6> renderFaces(const WoodModel& model, float pxPerMm, int samples = 1,
                                 const Progress& progress = {});

// The cut surface on `plane` (RGBA): the image covers the rectangle bounding the plane's intersection
// with the block, at pxPerMm; pixels outside the block are transparent. Orientation: see CutPlane.
// Throws InputError when the plane misses the block or the image would exceed 16384 px a side.
Image renderCut(const WoodModel& model, const CutPlane& plane, float pxPerMm, int samples = 1,
                const Progress& progress = {});

}  // namespace kerf
