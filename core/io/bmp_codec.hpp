#pragma once
// BMP files through stb_image (Debian's libstb, which tinygltf already brings into every Kerf program):
// the format of the Gran_1 log maps and colour bar, read by every log command. Through OpenImageIO they
// cost its 0.3 s load (io/oiio_codecs.hpp) in every `render-board`. Values as OpenImageIO gives them
// (v / 255); channels as stored (3, or 4 for BMPs with alpha; palettes expanded).
#include <filesystem>

#include "image/image.hpp"

namespace kerf {

// True when the file starts with "BM".
bool hasBmpSignature(const std::filesystem::path& path);

struct BmpHeader {
  int width = 0, height = 0, channels = 0;
};
BmpHeader readBmpHeader(const std::filesystem::path& path);  // InputError naming the file

// Decodes into `out`, sized by the caller to the header's size with its channels or with 3.
void readBmpPixels(const std::filesystem::path& path, Image& out);

}  // namespace kerf
