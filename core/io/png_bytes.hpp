#pragma once
// An image as the bytes of an 8-bit PNG file, in memory (OpenImageIO through an IOProxy): for formats
// that embed a PNG, such as binary glTF.
#include <vector>

#include "io/image.hpp"

namespace kerf {

// Throws InputError when OpenImageIO cannot encode.
std::vector<unsigned char> encodePng(const Image& image);

}  // namespace kerf
