#include "export/image_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "appearance/photo_true_appearance.hpp"
#include "export/export_formats.hpp"
#include "io/atomic_file.hpp"
#include "io/oiio_module.hpp"
#include "io/png_codec.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

constexpr float kMmPerInch = 25.4f;
constexpr float kRingHalfWidthPx = 0.75f;  // full intensity within, fading to 0 one pixel further

// Growth at every pixel centre (also just outside the block, so the ring gradient is defined at its edge).
template <typename PixelToBlock>
void fillGrowth(const WoodModel& model, LayeredImage& out, const PixelToBlock& pixelToBlock,
                const Progress& progress) {
  out.growth = Image(out.colour.width, out.colour.height, 1);
  parallelRows(
      out.colour.height,
      [&](int y) {
        for (int x = 0; x < out.colour.width; ++x)
          out.growth.pixel(x, y)[0] = model.material().year(pixelToBlock(x, y));
      },
      progress);
}

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The scale, in the attributes TIFF and EXR readers know (OpenImageIO's names).
void setScale(OiioPage& page, float pxPerMm, const std::string& description) {
  page.floatAttributes = {{"XResolution", pxPerMm * kMmPerInch},
                          {"YResolution", pxPerMm * kMmPerInch},
                          {"PixelAspectRatio", 1.0f},
                          {"Kerf:px_per_mm", pxPerMm},
                          {"Kerf:mm_per_pixel", 1.0f / pxPerMm}};
  page.textAttributes = {{"ResolutionUnit", "in"}, {"Software", "Kerf"}, {"ImageDescription", description}};
}

// Interleaves one image's channels after another's (same size).
Image interleave(std::initializer_list<const Image*> parts) {
  int channels = 0;
  for (const Image* p : parts) channels += p->channels;
  const Image& first = **parts.begin();
  Image out(first.width, first.height, channels);
  const std::size_t count = static_cast<std::size_t>(first.width) * first.height;
  for (std::size_t i = 0; i < count; ++i) {
    int c = 0;
    for (const Image* p : parts)
      for (int k = 0; k < p->channels; ++k) out.pixels[i * channels + c++] = p->pixels[i * p->channels + k];
  }
  return out;
}

// Whose colours the image shows: the procedural model's or the photo-true appearance's (issue 17); in the
// description too, as TIFF keeps no custom attribute.
std::string appearanceText(const LayeredImage& image) {
  return image.photoTrue ? "photo-true" : "procedural";
}
std::string colourName(const LayeredImage& image) {
  return image.photoTrue ? "colour (photo-true)" : "colour";
}

std::string floatText(float value) {
  std::ostringstream s;
  s.precision(9);
  s << value;
  return s.str();
}

std::string scaleText(float pxPerMm) {
  std::ostringstream s;
  s.precision(6);
  s << pxPerMm << " px/mm (" << pxPerMm * kMmPerInch << " dpi, " << 1.0f / pxPerMm << " mm per pixel)";
  return s.str();
}

OiioPage page(const Image& pixels, const std::string& type, std::vector<std::string> channelNames) {
  OiioPage out;
  out.pixels = &pixels;
  out.type = type;
  out.channelNames = std::move(channelNames);
  return out;
}

void writeWithOiio(const std::filesystem::path& path, const std::filesystem::path& temporary,
                   const std::vector<OiioPage>& pages) {
  const std::string error = oiioCodecs(path).writePages(path.string(), temporary.string(), pages);
  if (!error.empty()) throw InputError("cannot write " + path.string() + ": " + error);
}

void writePng(const std::filesystem::path& path, const std::filesystem::path& temporary,
              const LayeredImage& image, ImageLayer layer) {
  Image pixels = layer == ImageLayer::Colour  ? image.colour
                 : layer == ImageLayer::Rings ? image.rings
                                              : image.growth;
  const bool growth = layer == ImageLayer::Growth;
  PngWriteOptions options;
  options.bits = growth ? 16 : 8;
  options.pxPerMm = image.pxPerMm;
  const bool colour = layer == ImageLayer::Colour;
  std::string description =
      "Kerf " + (colour ? colourName(image) : imageLayerName(layer)) + ", " + scaleText(image.pxPerMm);
  std::string growthRange;
  if (growth) {  // 16-bit grey over the image's growth range (inside the block)
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (std::size_t i = 0; i < pixels.pixels.size(); ++i) {
      const bool inside = image.colour.channels < 4 || image.colour.pixels[i * 4 + 3] > 0.0f;
      if (inside) lo = std::min(lo, pixels.pixels[i]), hi = std::max(hi, pixels.pixels[i]);
    }
    if (lo > hi) lo = hi = 0.0f;
    const float span = hi > lo ? hi - lo : 1.0f;
    for (float& v : pixels.pixels) v = std::clamp((v - lo) / span, 0.0f, 1.0f);
    std::ostringstream range;
    range.precision(9);
    range << lo << " " << hi;
    growthRange = range.str();
    description += ", growth in years = min + value * (max - min), Kerf:growth_range = min max";
  }
  // The scale is in pHYs; PNG keeps the rest as text chunks, under the keys OpenImageIO reads back.
  options.text = {{"Software", "Kerf"},
                  {"Description", description},
                  {"Kerf:px_per_mm", floatText(image.pxPerMm)},
                  {"Kerf:mm_per_pixel", floatText(1.0f / image.pxPerMm)},
                  {"Kerf:layer", imageLayerName(layer)}};
  if (colour) options.text.push_back({"Kerf:appearance", appearanceText(image)});
  if (growth) options.text.push_back({"Kerf:growth_range", growthRange});
  writePngFile(temporary, pixels, options, path);
}

void writeTiff(const std::filesystem::path& path, const std::filesystem::path& temporary,
               const LayeredImage& image, bool extraLayers) {
  std::vector<OiioPage> pages{page(image.colour, "uint16", {})};
  setScale(pages[0], image.pxPerMm, "Kerf " + colourName(image) + ", " + scaleText(image.pxPerMm));
  pages[0].textAttributes.push_back({"Kerf:appearance", appearanceText(image)});
  if (image.colour.channels == 4) pages[0].intAttributes.push_back({"oiio:UnassociatedAlpha", 1});  // as PNG
  if (extraLayers) {
    OiioPage growth = page(image.growth, "float", {"growth"});
    setScale(growth, image.pxPerMm, "Kerf growth (years since the pith), " + scaleText(image.pxPerMm));
    OiioPage rings = page(image.rings, "uint16", {"rings"});
    setScale(rings, image.pxPerMm, "Kerf rings (ring-line overlay), " + scaleText(image.pxPerMm));
    pages.push_back(std::move(growth));
    pages.push_back(std::move(rings));
  }
  writeWithOiio(path, temporary, pages);
}

void writeExr(const std::filesystem::path& path, const std::filesystem::path& temporary,
              const LayeredImage& image, const ImageWriteOptions& options) {
  // EXR holds scene-linear values with premultiplied alpha; Kerf's colours are sRGB-encoded and straight.
  Image linear = image.colour;
  for (std::size_t i = 0; i < linear.pixels.size(); i += linear.channels) {
    const float alpha = linear.channels == 4 ? linear.pixels[i + 3] : 1.0f;
    for (int c = 0; c < 3; ++c) linear.pixels[i + c] = srgbToLinear(linear.pixels[i + c]) * alpha;
  }
  const Image pixels = options.extraLayers ? interleave({&linear, &image.growth, &image.rings}) : linear;
  const std::string colourType = options.exrHalf ? "half" : "float";
  OiioPage exr = page(pixels, colourType, {"R", "G", "B"});
  if (linear.channels == 4) {
    exr.channelNames.push_back("A");
    exr.alphaChannel = 3;
  }
  exr.channelTypes.assign(linear.channels, colourType);
  if (options.extraLayers) {
    exr.channelNames.push_back("growth");
    exr.channelTypes.push_back("float");  // years: half would blur the rings
    exr.channelNames.push_back("rings");
    exr.channelTypes.push_back(colourType);
  }
  setScale(exr, image.pxPerMm,
           "Kerf " + colourName(image) + " (linear)" +
               std::string(options.extraLayers ? ", growth (years), rings" : "") + ", " +
               scaleText(image.pxPerMm));
  exr.textAttributes.push_back({"compression", "zip"});
  exr.textAttributes.push_back({"Kerf:appearance", appearanceText(image)});
  writeWithOiio(path, temporary, {exr});
}

}  // namespace

ImageLayer imageLayerFromName(std::string_view name) {
  if (name == "colour" || name == "color") return ImageLayer::Colour;
  if (name == "growth") return ImageLayer::Growth;
  if (name == "rings") return ImageLayer::Rings;
  throw InputError("unknown image layer \"" + std::string(name) + "\" (use colour, growth or rings)");
}

void addRingLines(const WoodModel& model, LayeredImage& image) {
  const int w = image.growth.width, h = image.growth.height;
  image.rings = Image(w, h, 1);
  const float offset = model.params().ringOffset;
  const auto g = [&](int x, int y) {
    return image.growth.pixel(std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1))[0];
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Central differences, one-sided at the border (the clamped neighbour is the pixel itself).
      const int dx = std::min(x + 1, w - 1) - std::max(x - 1, 0),
                dy = std::min(y + 1, h - 1) - std::max(y - 1, 0);
      const float gx = dx > 0 ? (g(x + 1, y) - g(x - 1, y)) / dx : 0.0f;
      const float gy = dy > 0 ? (g(x, y + 1) - g(x, y - 1)) / dy : 0.0f;
      const float slope = std::max(std::hypot(gx, gy), 1e-6f);  // years per pixel
      const float t = g(x, y) - offset;
      const float distancePx = std::abs(t - std::round(t)) / slope;
      image.rings.pixel(x, y)[0] = std::clamp(1.0f + kRingHalfWidthPx - distancePx, 0.0f, 1.0f);
    }
  if (image.colour.channels == 4) {  // cuts: nothing outside the block
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (image.colour.pixel(x, y)[3] <= 0.0f)
          image.growth.pixel(x, y)[0] = image.rings.pixel(x, y)[0] = 0.0f;
  }
}

std::string imageLayerName(ImageLayer layer) {
  switch (layer) {
    case ImageLayer::Colour:
      return "colour";
    case ImageLayer::Growth:
      return "growth";
    case ImageLayer::Rings:
      return "rings";
  }
  return {};
}

LayeredImage renderFaceLayers(const WoodModel& model, FaceId face, float pxPerMm, int samples,
                              const Progress& progress, const PhotoTrueAppearance* photoTrue) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  LayeredImage out;
  out.pxPerMm = pxPerMm;
  const glm::ivec2 size = model.block().faceImageSize(face, pxPerMm);
  checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)), pxPerMm);
  out.photoTrue = photoTrue != nullptr;
  out.colour = photoTrue ? photoTrue->renderFace(face, size, progress.part(0.0, 0.8))
                         : renderFace(model, face, size, samples, progress.part(0.0, 0.8));
  fillGrowth(
      model, out, [&](int x, int y) { return model.block().pixelCenter(face, x, y, size); },
      progress.part(0.8, 1.0));
  addRingLines(model, out);
  return out;
}

LayeredImage renderCutLayers(const WoodModel& model, const CutPlane& plane, float pxPerMm, int samples,
                             const Progress& progress, const PhotoTrueAppearance* photoTrue) {
  LayeredImage out;
  out.pxPerMm = pxPerMm;
  out.photoTrue = photoTrue != nullptr;
  out.colour = photoTrue ? photoTrue->renderCut(plane, pxPerMm, progress.part(0.0, 0.8))
                         : renderCut(model, plane, pxPerMm, samples, progress.part(0.0, 0.8));
  const PlaneRect bounds = *plane.boundsInBlock(model.block());  // renderCut threw if there were none
  fillGrowth(
      model, out,
      [&](int x, int y) {
        return plane.toBlock({bounds.min.x + (x + 0.5f) / pxPerMm, bounds.max.y - (y + 0.5f) / pxPerMm});
      },
      progress.part(0.8, 1.0));
  addRingLines(model, out);
  return out;
}

void writeLayeredImage(const std::filesystem::path& path, const LayeredImage& image,
                       const ImageWriteOptions& options) {
  if (image.colour.empty()) throw InputError("refusing to write an empty image to " + path.string());
  const ExportFormat format = requireExportFormat(path, ExportKind::Image, "an image").format;
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    if (format == ExportFormat::Png) {
      writePng(path, temporary, image, options.pngLayer);
    } else if (format == ExportFormat::Exr) {
      writeExr(path, temporary, image, options);
    } else {
      writeTiff(path, temporary, image, options.extraLayers);
    }
    verifyWrittenImage(temporary, path);
  });
}

ExportedImageInfo readExportedImageInfo(const std::filesystem::path& path) {
  ExportedImageInfo info;
  if (hasPngSignature(path)) {
    const PngInfo png = readPngInfo(path);
    static const char* const kChannelNames[] = {"Y", "Y,A", "R,G,B", "R,G,B,A"};
    info.width = png.header.width;
    info.height = png.header.height;
    info.channels = png.header.channels;
    info.subimages = 1;
    info.channelNames = info.channels >= 1 && info.channels <= 4 ? kChannelNames[info.channels - 1] : "";
    info.bitsPerChannel = png.header.bits == 16 ? "uint16" : "uint8";
    info.dotsPerInch = png.pixelsPerMetre * kMmPerInch / 1000.0f;
    for (const PngText& text : png.text)
      if (text.key == "Kerf:mm_per_pixel") info.mmPerPixel = std::strtof(text.value.c_str(), nullptr);
    return info;
  }
  OiioFileInfo file;
  const std::string error = oiioCodecs(path).readInfo(path.string(), file);
  if (!error.empty()) throw InputError("cannot read image " + path.string() + ": " + error);
  info.width = file.width;
  info.height = file.height;
  info.channels = file.channels;
  info.subimages = file.subimages;
  info.channelNames = file.channelNames;
  info.bitsPerChannel = file.firstChannelType;
  info.dotsPerInch = file.resolutionUnit == "cm" ? file.xResolution * 2.54f : file.xResolution;
  info.mmPerPixel = file.mmPerPixel;
  return info;
}

}  // namespace kerf
