#pragma once
// Conversions between core's float images and Qt's 8-bit ones, for display.
#include <QImage>

#include "io/image.hpp"

namespace kerf {

// Float 0..1 (grey, RGB or RGBA) -> QImage (RGB888, or RGBA8888 with 4 channels). Values are clamped
// and rounded. Safe on any thread. An empty image gives a null QImage.
QImage toQImage(const Image& image);

// QImage (any format) -> float 0..1 RGB, the inverse for photos. A null QImage gives an empty image.
Image fromQImage(const QImage& photo);

}  // namespace kerf
