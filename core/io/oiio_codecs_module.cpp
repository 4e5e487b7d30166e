// The OpenImageIO module (io/oiio_codecs.hpp): every image format but PNG, loaded on first use. Built as
// its own shared module, not into kerf_core: nothing here may throw out of it, and it uses nothing of
// Kerf's but the Image struct.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>

#include "io/oiio_codecs.hpp"

namespace kerf {
namespace {

std::unique_ptr<OIIO::ImageInput> openInput(const std::string& path, std::string& error) {
  // Kerf drops alpha, so it wants the colour as stored: without this hint OpenImageIO multiplies it by
  // alpha, and transparent parts of a photo would read as black.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) error = OIIO::geterror();
  if (error.empty() && !in) error = "unknown format";
  return in;
}

std::size_t countNonFinite(const std::vector<float>& values, int channels);

// EXIF Orientation (TIFF tag 274): how the stored pixels must be turned and mirrored to be seen as the
// photographer saw them. Phones store upright photos sideways with 6 or 8. Out-of-range values: as stored.
int orientationOf(const OIIO::ImageSpec& spec) {
  const int orientation = spec.get_int_attribute("Orientation", 1);
  return orientation >= 1 && orientation <= 8 ? orientation : 1;
}

// A photo with an EXIF orientation, read through an ImageBuf and turned upright by OpenImageIO's own
// reorient, then into `out` (its channels, or RGB with grey replicated and alpha dropped). The turning is
// done in the file's own pixel type (a phone JPEG: 8 bits), so the only float copy is `out`, as for
// every other read (io/image.cpp checks the memory for that one).
std::string readReoriented(const std::string& path, const OIIO::ImageSpec& config, Image& out,
                           std::size_t& nonFinite) {
  OIIO::ImageBuf stored(path, 0, 0, nullptr, &config);
  if (!stored.read(0, 0, true)) return stored.geterror();
  OIIO::ImageBuf upright = OIIO::ImageBufAlgo::reorient(stored);
  if (upright.has_error()) return upright.geterror();
  stored.reset();  // the stored copy is not needed any more
  const int channels = upright.spec().nchannels;
  if (upright.spec().width != out.width || upright.spec().height != out.height ||
      (out.channels != channels && out.channels != 3))
    return "the file changed while being read";
  OIIO::ROI roi = upright.roi();
  if (out.channels != channels && channels >= 3) {
    roi.chend = 3;  // alpha and further channels dropped as they are read out
  } else if (out.channels != channels) {
    const int grey[3] = {0, 0, 0};
    upright = OIIO::ImageBufAlgo::channels(upright, 3, grey);
    if (upright.has_error()) return upright.geterror();
    roi = upright.roi();
  }
  if (!upright.get_pixels(roi, OIIO::TypeDesc::FLOAT, out.pixels.data())) return upright.geterror();
  nonFinite = countNonFinite(out.pixels, out.channels);
  return {};
}

std::string readHeader(const std::string& path, OiioHeader& header) try {
  std::string error;
  auto in = openInput(path, error);
  if (!in) return error;
  header.orientation = orientationOf(in->spec());
  const bool turned = header.orientation >= 5;  // 5 to 8 turn the image by a quarter
  header.width = turned ? in->spec().height : in->spec().width;
  header.height = turned ? in->spec().width : in->spec().height;
  header.channels = in->spec().nchannels;
  header.format = in->format_name();
  return {};
} catch (const std::exception& e) {
  return e.what();
}

std::size_t countNonFinite(const std::vector<float>& values, int channels) {
  std::size_t count = 0;
  for (std::size_t p = 0; p < values.size(); p += channels)
    count += std::any_of(values.begin() + p, values.begin() + p + channels,
                         [](float v) { return !std::isfinite(v); });
  return count;
}

std::string readPixels(const std::string& path, Image& out, std::size_t& nonFinite) try {
  std::string error;
  auto in = openInput(path, error);
  if (!in) return error;
  const OIIO::ImageSpec& spec = in->spec();
  nonFinite = 0;
  if (orientationOf(spec) != 1) {
    in.reset();
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return readReoriented(path, config, out, nonFinite);
  }
  if (spec.width != out.width || spec.height != out.height ||
      (out.channels != spec.nchannels && out.channels != 3))
    return "the file changed while being read";
  if (out.channels == spec.nchannels) {
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.pixels.data()))
      return in->geterror();
    nonFinite = countNonFinite(out.pixels, spec.nchannels);
    return {};
  }
  // One float copy of the image is all a read takes: an image with other than 3 channels is decoded a
  // strip of rows at a time into the RGB result (a 10950 x 10950 RGBA image took 3.4 GB as an RGBA copy
  // and an RGB copy, then 1.4 GB).
  constexpr int kStripRows = 64;
  std::vector<float> strip;
  for (int row = 0; row < spec.height; row += kStripRows) {
    const int rows = std::min(kStripRows, spec.height - row);
    strip.resize(static_cast<std::size_t>(rows) * spec.width * spec.nchannels);
    if (!in->read_scanlines(0, 0, spec.y + row, spec.y + row + rows, spec.z, 0, spec.nchannels,
                            OIIO::TypeDesc::FLOAT, strip.data()))
      return in->geterror();
    nonFinite += countNonFinite(strip, spec.nchannels);
    // Grey is replicated into R, G and B; alpha and any further channel are dropped.
    for (std::size_t p = 0; p < static_cast<std::size_t>(rows) * spec.width; ++p) {
      const float* from = &strip[p * spec.nchannels];
      float* to = out.pixel(0, row) + p * 3;
      for (int c = 0; c < 3; ++c) to[c] = from[spec.nchannels >= 3 ? c : 0];
    }
  }
  return {};
} catch (const std::exception& e) {
  return e.what();
}

OIIO::ImageSpec specOf(const OiioPage& page) {
  OIIO::ImageSpec spec(page.pixels->width, page.pixels->height, page.pixels->channels,
                       OIIO::TypeDesc(page.type));
  if (!page.channelNames.empty()) spec.channelnames = page.channelNames;
  if (!page.channelTypes.empty()) {
    spec.channelformats.clear();
    for (const std::string& type : page.channelTypes) spec.channelformats.emplace_back(type);
  }
  if (page.alphaChannel >= 0) spec.alpha_channel = page.alphaChannel;
  for (const auto& [name, value] : page.textAttributes) spec.attribute(name, value);
  for (const auto& [name, value] : page.floatAttributes) spec.attribute(name, value);
  for (const auto& [name, value] : page.intAttributes) spec.attribute(name, value);
  return spec;
}

std::string writePages(const std::string& path, const std::string& temporary,
                       const std::vector<OiioPage>& pages) try {
  if (pages.empty()) return "nothing to write";
  // OpenImageIO picks the format from the extension, which the temporary file keeps.
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return OIIO::geterror();
  std::vector<OIIO::ImageSpec> specs;
  for (const OiioPage& page : pages) specs.push_back(specOf(page));
  if (specs.size() > 1 && !out->supports("multiimage"))
    return "this OpenImageIO cannot write several pages to it";
  const bool opened = specs.size() == 1 ? out->open(temporary, specs[0])
                                        : out->open(temporary, static_cast<int>(specs.size()), specs.data());
  if (!opened) return out->geterror();
  for (std::size_t s = 0; s < specs.size(); ++s) {
    if (s > 0 && !out->open(temporary, specs[s], OIIO::ImageOutput::AppendSubimage)) return out->geterror();
    if (!out->write_image(OIIO::TypeDesc::FLOAT, pages[s].pixels->pixels.data())) return out->geterror();
  }
  if (!out->close()) return out->geterror();
  return {};
} catch (const std::exception& e) {
  return e.what();
}

std::string readInfo(const std::string& path, OiioFileInfo& info) try {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  info.width = spec.width;
  info.height = spec.height;
  info.channels = spec.nchannels;
  for (const std::string& name : spec.channelnames)
    info.channelNames += (info.channelNames.empty() ? "" : ",") + name;
  info.firstChannelType = spec.channelformat(0).c_str();
  info.resolutionUnit = spec.get_string_attribute("ResolutionUnit");
  info.xResolution = spec.get_float_attribute("XResolution", 0.0f);
  if (const OIIO::ParamValue* mm = spec.find_attribute("Kerf:mm_per_pixel"))
    info.mmPerPixel = mm->type() == OIIO::TypeDesc::STRING ? std::stof(mm->get_string()) : mm->get_float();
  info.subimages = 0;
  while (in->seek_subimage(info.subimages, 0)) ++info.subimages;
  return {};
} catch (const std::exception& e) {
  return e.what();
}

const OiioCodecs kCodecs{kOiioCodecsVersion, readHeader, readPixels, writePages, readInfo};

}  // namespace
}  // namespace kerf

extern "C" const kerf::OiioCodecs* kerf_oiio_codecs() {
  return &kerf::kCodecs;
}
