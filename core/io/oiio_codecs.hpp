#pragma once
// The image formats other than PNG (JPEG, TIFF, EXR, ...) go through OpenImageIO, built into a module of
// its own (target kerf_oiio_codecs, io/oiio_codecs_module.cpp) that io/oiio_module.hpp loads the first
// time such a file is read or written. OpenImageIO links 260 shared libraries (FFmpeg, GDAL, DCMTK ...);
// loaded with every program they took 0.3 s of each kerf-cli run (issue 19 item 5). This header is the
// whole interface between the two: plain data and function pointers, no exception crosses it.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "image/image.hpp"

namespace kerf {

inline constexpr int kOiioCodecsVersion = 2;

struct OiioHeader {
  // As the image is shown: a photo whose EXIF Orientation says it was taken turned (a phone held upright,
  // 5 to 8) has its width and height swapped here, and readPixels turns its pixels the same way.
  int width = 0, height = 0, channels = 0;
  int orientation = 1;  // the file's EXIF Orientation (1 = as stored, 2 to 8 = mirrored and / or turned)
  std::string format;   // OpenImageIO's format name: "jpeg", "tiff", "openexr" ...
};

// One subimage to write: the pixels and how OpenImageIO stores them.
struct OiioPage {
  const Image* pixels = nullptr;
  std::string type = "uint8";             // OpenImageIO type name: uint8, uint16, half, float
  std::vector<std::string> channelNames;  // empty: OpenImageIO's defaults
  std::vector<std::string> channelTypes;  // one per channel; empty: all `type`
  int alphaChannel = -1;
  std::vector<std::pair<std::string, std::string>> textAttributes;
  std::vector<std::pair<std::string, float>> floatAttributes;
  std::vector<std::pair<std::string, int>> intAttributes;
};

struct OiioFileInfo {
  int width = 0, height = 0, channels = 0, subimages = 0;
  std::string channelNames;      // comma-separated, first subimage
  std::string firstChannelType;  // "uint8", "half" ...
  std::string resolutionUnit;    // "in", "cm" or empty
  float xResolution = 0;
  float mmPerPixel = 0;  // the Kerf:mm_per_pixel attribute, 0 if absent
};

// Each function returns an empty string on success, else what went wrong (OpenImageIO's message).
struct OiioCodecs {
  int version = kOiioCodecsVersion;
  std::string (*readHeader)(const std::string& path, OiioHeader& header);
  // `out` is sized by the caller to the header's size, with the file's channels or with 3 (grey
  // replicated, alpha and further channels dropped). Counts the pixels with a non-finite value.
  std::string (*readPixels)(const std::string& path, Image& out, std::size_t& nonFinitePixels);
  // The format follows `path`'s extension; the pages are written to `temporary`.
  std::string (*writePages)(const std::string& path, const std::string& temporary,
                            const std::vector<OiioPage>& pages);
  std::string (*readInfo)(const std::string& path, OiioFileInfo& info);
};

}  // namespace kerf

// The module's one entry point.
extern "C" const kerf::OiioCodecs* kerf_oiio_codecs();
