#pragma once
// PNG files through libpng itself: Kerf's own format (photos, renders, exports, the textures of binary
// glTF parts). Every other format goes through OpenImageIO, loaded only when such a file is met
// (io/oiio_module.hpp): OpenImageIO brings 260 shared libraries, and loading them took 0.3 s of every
// kerf-cli run, more than rendering a 1200 x 1200 board (issue 19 item 5).
//
// Values as OpenImageIO gives and takes them, so that files and goldens are the same either way: reading,
// 8-bit v -> v / 255 and 16-bit v -> v / 65535; writing, v -> clamp(v * max + 0.5) truncated. Palette and
// low-bit grey PNGs are expanded to 8 bits; transparency becomes an alpha channel, kept as stored
// (unassociated). Errors are InputError naming the file.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace kerf {

// True when the file starts with the PNG signature (whatever its extension says).
bool hasPngSignature(const std::filesystem::path& path);

struct PngHeader {
  int width = 0, height = 0;
  int channels = 0;  // as decoded: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA (palettes expanded)
  int bits = 8;      // 8 or 16 per channel, as decoded
};
PngHeader readPngHeader(const std::filesystem::path& path);

// Decodes into `out`, which the caller sized to the header's width and height: with the header's
// channels, or with 3 (grey is replicated, alpha dropped).
void readPngPixels(const std::filesystem::path& path, Image& out);

struct PngText {
  std::string key, value;  // a tEXt chunk; keys are 1-79 Latin-1 characters
};

struct PngWriteOptions {
  int bits = 8;       // 8 or 16 per channel
  float pxPerMm = 0;  // > 0: written as the pHYs chunk (pixels per metre)
  std::vector<PngText> text;
};

// Writes 1-4 channel images (grey, grey + alpha, RGB, RGBA) to `path` as it is (callers make it atomic).
// `target` names the file in messages.
void writePngFile(const std::filesystem::path& path, const Image& image, const PngWriteOptions& options = {},
                  const std::filesystem::path& target = {});
std::vector<unsigned char> encodePngBytes(const Image& image, const PngWriteOptions& options = {});

struct PngInfo {
  PngHeader header;          // channels and bits as stored for grey and RGB(A) files
  float pixelsPerMetre = 0;  // from pHYs, 0 without one (or with an unknown unit)
  std::vector<PngText> text;
};
PngInfo readPngInfo(const std::filesystem::path& path);

}  // namespace kerf
