#pragma once
// Where the model departs from a photo, pixel by pixel: the heat map of the faces view's Difference
// display, and its colour scale (for the legend).
//
// Registration: a photo and a model rendering each cover their whole face (the faces view stretches
// either over the face's rectangle, whatever its resolution), so the model is resampled to the photo's
// size and photo pixel (x, y) meets the model at the same face position.
//
// Colours: black where the model matches the photo; towards orange where the model's wood is lighter
// than the photo, towards blue where it is darker, towards white where it has another hue at the same
// lightness. Full colour at kDifferenceFullScale (of 255), the difference averaged over R, G and B.
#include <QImage>
#include <array>

namespace kerf {

inline constexpr int kDifferenceFullScale = 64;

// The colour of a mean absolute difference `difference` (0..255) whose lightness change (model minus
// photo, -255..255) is `lighter`.
QRgb differenceColour(int difference, int lighter);

// The heat map on the photo's pixel grid (Format_RGB32); null when either image is null.
QImage differenceHeatMap(const QImage& photo, const QImage& model);

// Faces A..F; a face without a photo or without a model gets a null image.
std::array<QImage, 6> differenceHeatMaps(const std::array<QImage, 6>& photos,
                                         const std::array<QImage, 6>& models);

}  // namespace kerf
