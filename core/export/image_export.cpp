#include "export/image_export.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "export/export_formats.hpp"
#include "io/atomic_file.hpp"
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

void setScale(OIIO::ImageSpec& spec, float pxPerMm, const std::string& description) {
  spec.attribute("XResolution", pxPerMm * kMmPerInch);
  spec.attribute("YResolution", pxPerMm * kMmPerInch);
  spec.attribute("ResolutionUnit", "in");
  spec.attribute("PixelAspectRatio", 1.0f);
  spec.attribute("Kerf:px_per_mm", pxPerMm);
  spec.attribute("Kerf:mm_per_pixel", 1.0f / pxPerMm);
  spec.attribute("Software", "Kerf");
  spec.attribute("ImageDescription", description);
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

void check(bool ok, OIIO::ImageOutput& out, const std::filesystem::path& path) {
  if (!ok) throw InputError("cannot write " + path.string() + ": " + out.geterror());
}

void writePng(const std::filesystem::path& path, const std::filesystem::path& temporary,
              const LayeredImage& image, ImageLayer layer) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw InputError("cannot write " + path.string() + ": " + OIIO::geterror());
  Image pixels = layer == ImageLayer::Colour  ? image.colour
                 : layer == ImageLayer::Rings ? image.rings
                                              : image.growth;
  const bool growth = layer == ImageLayer::Growth;
  OIIO::ImageSpec spec(pixels.width, pixels.height, pixels.channels,
                       growth ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  std::string description = "Kerf " + imageLayerName(layer) + ", " + scaleText(image.pxPerMm);
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
    spec.attribute("Kerf:growth_range", range.str());
    description += ", growth in years = min + value * (max - min), Kerf:growth_range = min max";
  }
  setScale(spec, image.pxPerMm, description);
  // PNG keeps only text attributes (tEXt chunks); the scale itself is in pHYs (XResolution).
  spec.attribute("Kerf:px_per_mm", floatText(image.pxPerMm));
  spec.attribute("Kerf:mm_per_pixel", floatText(1.0f / image.pxPerMm));
  spec.attribute("Kerf:layer", imageLayerName(layer));
  check(out->open(temporary.string(), spec), *out, path);
  check(out->write_image(OIIO::TypeDesc::FLOAT, pixels.pixels.data()), *out, path);
  check(out->close(), *out, path);
}

void writeTiff(const std::filesystem::path& path, const std::filesystem::path& temporary,
               const LayeredImage& image, bool extraLayers) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw InputError("cannot write " + path.string() + ": " + OIIO::geterror());
  const int w = image.colour.width, h = image.colour.height;
  std::vector<OIIO::ImageSpec> specs;
  specs.emplace_back(w, h, image.colour.channels, OIIO::TypeDesc::UINT16);
  setScale(specs.back(), image.pxPerMm, "Kerf colour, " + scaleText(image.pxPerMm));
  if (image.colour.channels == 4) specs.back().attribute("oiio:UnassociatedAlpha", 1);  // straight, as PNG
  std::vector<const Image*> pages{&image.colour};
  if (extraLayers) {
    specs.emplace_back(w, h, 1, OIIO::TypeDesc::FLOAT);
    specs.back().channelnames = {"growth"};
    setScale(specs.back(), image.pxPerMm, "Kerf growth (years since the pith), " + scaleText(image.pxPerMm));
    specs.emplace_back(w, h, 1, OIIO::TypeDesc::UINT16);
    specs.back().channelnames = {"rings"};
    setScale(specs.back(), image.pxPerMm, "Kerf rings (ring-line overlay), " + scaleText(image.pxPerMm));
    pages.push_back(&image.growth);
    pages.push_back(&image.rings);
  }
  if (specs.size() > 1 && !out->supports("multiimage"))
    throw InputError("this OpenImageIO cannot write multi-page TIFF");
  check(out->open(temporary.string(), static_cast<int>(specs.size()), specs.data()), *out, path);
  for (std::size_t s = 0; s < specs.size(); ++s) {
    if (s > 0) check(out->open(temporary.string(), specs[s], OIIO::ImageOutput::AppendSubimage), *out, path);
    check(out->write_image(OIIO::TypeDesc::FLOAT, pages[s]->pixels.data()), *out, path);
  }
  check(out->close(), *out, path);
}

void writeExr(const std::filesystem::path& path, const std::filesystem::path& temporary,
              const LayeredImage& image, const ImageWriteOptions& options) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw InputError("cannot write " + path.string() + ": " + OIIO::geterror());
  // EXR holds scene-linear values with premultiplied alpha; Kerf's colours are sRGB-encoded and straight.
  Image linear = image.colour;
  for (std::size_t i = 0; i < linear.pixels.size(); i += linear.channels) {
    const float alpha = linear.channels == 4 ? linear.pixels[i + 3] : 1.0f;
    for (int c = 0; c < 3; ++c) linear.pixels[i + c] = srgbToLinear(linear.pixels[i + c]) * alpha;
  }
  const Image pixels = options.extraLayers ? interleave({&linear, &image.growth, &image.rings}) : linear;
  const OIIO::TypeDesc colourType = options.exrHalf ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(pixels.width, pixels.height, pixels.channels, colourType);
  spec.channelnames = {"R", "G", "B"};
  if (linear.channels == 4) {
    spec.channelnames.push_back("A");
    spec.alpha_channel = 3;
  }
  spec.channelformats.assign(linear.channels, colourType);
  if (options.extraLayers) {
    spec.channelnames.push_back("growth");
    spec.channelformats.push_back(OIIO::TypeDesc::FLOAT);  // years: half would blur the rings
    spec.channelnames.push_back("rings");
    spec.channelformats.push_back(colourType);
  }
  setScale(spec, image.pxPerMm,
           "Kerf colour (linear)" + std::string(options.extraLayers ? ", growth (years), rings" : "") + ", " +
               scaleText(image.pxPerMm));
  spec.attribute("compression", "zip");
  check(out->open(temporary.string(), spec), *out, path);
  check(out->write_image(OIIO::TypeDesc::FLOAT, pixels.pixels.data()), *out, path);
  check(out->close(), *out, path);
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
                              const Progress& progress) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  LayeredImage out;
  out.pxPerMm = pxPerMm;
  const glm::ivec2 size = model.block().faceImageSize(face, pxPerMm);
  checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)), pxPerMm);
  out.colour = renderFace(model, face, size, samples, progress.part(0.0, 0.8));
  fillGrowth(
      model, out, [&](int x, int y) { return model.block().pixelCenter(face, x, y, size); },
      progress.part(0.8, 1.0));
  addRingLines(model, out);
  return out;
}

LayeredImage renderCutLayers(const WoodModel& model, const CutPlane& plane, float pxPerMm, int samples,
                             const Progress& progress) {
  LayeredImage out;
  out.pxPerMm = pxPerMm;
  out.colour = renderCut(model, plane, pxPerMm, samples, progress.part(0.0, 0.8));
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
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError("cannot read image " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  ExportedImageInfo info;
  info.width = spec.width;
  info.height = spec.height;
  info.channels = spec.nchannels;
  for (const std::string& name : spec.channelnames)
    info.channelNames += (info.channelNames.empty() ? "" : ",") + name;
  info.bitsPerChannel = spec.channelformat(0).c_str();
  const std::string unit = spec.get_string_attribute("ResolutionUnit");
  const float x = spec.get_float_attribute("XResolution", 0.0f);
  info.dotsPerInch = unit == "cm" ? x * 2.54f : x;
  const OIIO::ParamValue* mm = spec.find_attribute("Kerf:mm_per_pixel");
  if (mm)
    info.mmPerPixel = mm->type() == OIIO::TypeDesc::STRING ? std::stof(mm->get_string()) : mm->get_float();
  while (in->seek_subimage(info.subimages, 0)) ++info.subimages;
  return info;
}

}  // namespace kerf
