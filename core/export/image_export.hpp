#pragma once
// Face and cut images at true scale, with the growth field and a ring-line overlay as extra layers, written
// (PNG with libpng, TIFF and EXR with OpenImageIO) with their scale in the file (docs/export.md):
//   PNG  8-bit, one layer per file (colour RGB / RGBA for cuts, rings grey; growth 16-bit grey scaled to
//        the image's growth range, stored in the "Kerf:growth_range" text attribute);
//   TIFF 16-bit colour, then one page per extra layer: growth as 32-bit float years, rings 16-bit grey;
//   EXR  one part with the channels R,G,B[,A] (half or float), growth (always float, years), rings.
// Every file carries XResolution/YResolution in dots per inch (ResolutionUnit "in"), PixelAspectRatio 1
// and the custom attributes Kerf:px_per_mm and Kerf:mm_per_pixel.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "io/image.hpp"
#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

class PhotoTrueAppearance;

enum class ImageLayer { Colour, Growth, Rings };
ImageLayer imageLayerFromName(std::string_view name);  // colour|color|growth|rings; InputError otherwise
std::string imageLayerName(ImageLayer layer);

// A rendered face or cut with its layers, all the same size. Outside the block (cuts) growth and rings
// are 0 and the colour's alpha is 0.
struct LayeredImage {
  Image colour;  // RGB (faces) or RGBA (cuts): exactly what renderFace / renderCut give
  Image growth;  // 1 channel: growth time in years at each pixel centre (WoodMaterial::year)
  Image rings;   // 1 channel in [0, 1]: anti-aliased lines about 1.5 px wide on the ring levels
  float pxPerMm = 1.0f;
  bool photoTrue = false;  // the colour is the photo-true appearance's (written as Kerf:appearance)
};

// Face images are sized as Block::faceImageSize; the colour carries the face's photo tint, as render-faces.
// With `photoTrue` the colour is its renderFace / renderCut (samples apply to the procedural colour only);
// growth and rings are the field's either way.
LayeredImage renderFaceLayers(const WoodModel& model, FaceId face, float pxPerMm, int samples,
                              const Progress& progress = {}, const PhotoTrueAppearance* photoTrue = nullptr);
// Throws InputError when the plane misses the block (as renderCut).
LayeredImage renderCutLayers(const WoodModel& model, const CutPlane& plane, float pxPerMm, int samples,
                             const Progress& progress = {}, const PhotoTrueAppearance* photoTrue = nullptr);

// Fills image.rings from image.growth (same size): lines on the model's ring levels (growth.ring_offset + k),
// and zeroes growth and rings where the colour's alpha is 0.
void addRingLines(const WoodModel& model, LayeredImage& image);

struct ImageWriteOptions {
  ImageLayer pngLayer = ImageLayer::Colour;  // the one layer a PNG holds
  bool extraLayers = true;                   // growth + rings in TIFF pages / EXR channels
  bool exrHalf = true;                       // EXR colour and rings as half (else float); growth is float
};

// Writes by extension (.png, .tif/.tiff, .exr), atomically. Throws InputError (other extension, write error).
void writeLayeredImage(const std::filesystem::path& path, const LayeredImage& image,
                       const ImageWriteOptions& options = {});

// What an exported image says about its scale and layers, read back with OpenImageIO (tests, re-import).
struct ExportedImageInfo {
  int width = 0, height = 0, channels = 0, subimages = 0;
  float dotsPerInch = 0;       // XResolution when ResolutionUnit is inches (converted from cm if needed)
  float mmPerPixel = 0;        // Kerf:mm_per_pixel, 0 if absent
  std::string channelNames;    // comma-separated, first subimage
  std::string bitsPerChannel;  // OIIO's name of the first channel's type ("uint8", "half", ...)
};
ExportedImageInfo readExportedImageInfo(const std::filesystem::path& path);

}  // namespace kerf
