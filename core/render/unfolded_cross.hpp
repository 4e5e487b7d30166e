#pragma once
// The six faces laid out as the unfolded cross of Mokume A.1.1 (B above A, D below, C left, E and F
// to the right), so rings can be followed across the shared edges. Used for previews and docs.
#include <array>

#include "geometry/block.hpp"
#include "image/image.hpp"

namespace kerf {

// Faces in A..F order, all at the same pixels per mm (as renderFaces gives them). Empty slots are
// filled with `background`; the images must have 3 channels.
Image unfoldedCross(const std::array<Image, 6>& faces, const Block& block, float background = 0.18f);

}  // namespace kerf
