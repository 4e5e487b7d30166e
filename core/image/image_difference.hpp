#pragma once
// How far two images of the same size are apart (the golden-image and parity tests).
#include "image/image.hpp"

namespace kerf {

// Mean absolute difference per channel value, and the share of pixels whose largest channel
// difference exceeds `pixelTolerance`. Sizes must match (throws InputError otherwise).
struct ImageDifference {
  double meanAbs = 0;
  double shareOverTolerance = 0;
};
ImageDifference compareImages(const Image& a, const Image& b, float pixelTolerance);

}  // namespace kerf
