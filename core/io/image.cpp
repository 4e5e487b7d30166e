#include "io/image.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

std::unique_ptr<OIIO::ImageInput> openInput(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError("image not found: " + path.string());
  checkInputFile(path, "image", kMaxImageFileBytes);  // a FIFO or /dev/zero must not block or feed us
  // Kerf drops alpha, so it wants the colour as stored: without this hint OpenImageIO multiplies it by
  // alpha, and transparent parts of a PNG photo would read as black.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) {
    throw InputError("cannot read image " + path.string() + ": " + OIIO::geterror());
  }
  return in;
}

// A PNG cut short (an interrupted copy) has no IEND chunk near its end. Refusing it here gives a clear
// message, and keeps it away from libpng's error path, where OpenImageIO leaks its message string.
void checkPngComplete(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : 0;
  const std::streamoff tail = std::min<std::streamoff>(size, 65536);
  std::string bytes(static_cast<std::size_t>(tail), '\0');
  if (!in.seekg(size - tail) || !in.read(bytes.data(), tail) || bytes.find("IEND") == std::string::npos) {
    throw InputError("cannot decode image " + path.string() + ": the PNG file is truncated (it has no end)");
  }
}

}  // namespace

glm::ivec2 readImageSize(const std::filesystem::path& path) {
  auto in = openInput(path);
  const OIIO::ImageSpec& spec = in->spec();
  return {spec.width, spec.height};
}

Image readImage(const std::filesystem::path& path, bool keepChannels) {
  auto in = openInput(path);
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw InputError("image " + path.string() + " is empty");
  }
  const long long pixelCount = static_cast<long long>(spec.width) * spec.height;
  if (pixelCount > kMaxImagePixels) {
    throw InputError("image " + path.string() + " is " + std::to_string(spec.width) + " x " +
                     std::to_string(spec.height) + " pixels; Kerf reads images up to " +
                     std::to_string(kMaxImagePixels / 1'000'000) +
                     " megapixels. Scale the photo down first.");
  }
  if (spec.nchannels > 16) {
    throw InputError("image " + path.string() + " has " + std::to_string(spec.nchannels) +
                     " channels; Kerf reads grey, RGB and RGBA images");
  }
  if (std::string(in->format_name()) == "png") checkPngComplete(path);
  // One float copy of the image is all a read takes: an image with other than 3 channels is decoded a
  // strip of rows at a time into the RGB result (a 10950 x 10950 RGBA PNG took 3.4 GB as an RGBA copy
  // and an RGB copy, now 1.4 GB). That copy must fit the memory budget, checked before it is taken.
  const int channels = keepChannels ? spec.nchannels : 3;
  checkImageReadMemory(path.string(), spec.width, spec.height, channels);
  Image out(spec.width, spec.height, channels);
  std::size_t nonFinite = 0;
  // Float TIFF and EXR photos can hold NaN or infinity; one such pixel spreads through every filter and
  // fit that reads it (it crashed detect). Refused, naming how many, rather than guessed at.
  const auto countNonFinite = [&](const std::vector<float>& values) {
    for (std::size_t p = 0; p < values.size(); p += spec.nchannels)
      for (int c = 0; c < spec.nchannels; ++c)
        if (!std::isfinite(values[p + c])) {
          ++nonFinite;
          break;
        }
  };
  if (channels == spec.nchannels) {
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.pixels.data()))
      throw InputError("cannot decode image " + path.string() + ": " + in->geterror());
    countNonFinite(out.pixels);
  } else {
    constexpr int kStripRows = 64;
    std::vector<float> strip;
    for (int row = 0; row < spec.height; row += kStripRows) {
      const int rows = std::min(kStripRows, spec.height - row);
      strip.resize(static_cast<std::size_t>(rows) * spec.width * spec.nchannels);
      if (!in->read_scanlines(0, 0, spec.y + row, spec.y + row + rows, spec.z, 0, spec.nchannels,
                              OIIO::TypeDesc::FLOAT, strip.data()))
        throw InputError("cannot decode image " + path.string() + ": " + in->geterror());
      countNonFinite(strip);
      // Grey is replicated into R, G and B; alpha and any further channel are dropped.
      for (std::size_t p = 0; p < static_cast<std::size_t>(rows) * spec.width; ++p) {
        const float* from = &strip[p * spec.nchannels];
        float* to = out.pixel(0, row) + p * 3;
        for (int c = 0; c < 3; ++c) to[c] = from[spec.nchannels >= 3 ? c : 0];
      }
    }
  }
  if (nonFinite > 0) {
    throw InputError(
        "image " + path.string() + " has " + std::to_string(nonFinite) +
        (nonFinite == 1 ? " pixel that is not a finite number" : " pixels that are not finite numbers") +
        " (NaN or infinity); save it again without them");
  }
  return out;
}

void writeImage(const std::filesystem::path& path, const Image& image, int bits) {
  if (image.empty()) throw InputError("refusing to write an empty image to " + path.string());
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    // OIIO picks the format from the extension, so the temporary file keeps it.
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw InputError("cannot write " + path.string() + ": " + OIIO::geterror());
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
    if (!out->open(temporary.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close()) {
      throw InputError("cannot write " + path.string() + ": " + out->geterror());
    }
    verifyWrittenImage(temporary, path);
  });
}

void verifyWrittenImage(const std::filesystem::path& written, const std::filesystem::path& target) {
  std::string extension = written.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") return;  // the TIFF and EXR writers report a failed write themselves
  // A complete PNG ends with its IEND chunk. (Decoding it again would also tell, but libpng's error
  // path leaks OpenImageIO's message string, and it costs a decode.)
  static const char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', '\xae', '\x42', '\x60', '\x82'};
  std::ifstream in(written, std::ios::binary | std::ios::ate);
  char tail[12] = {};
  const bool complete = in && in.tellg() >= 12 && in.seekg(-12, std::ios::end) && in.read(tail, 12) &&
                        std::equal(tail, tail + 12, kIend);
  if (!complete) {
    throw InputError("cannot write " + target.string() +
                     ": the file could not be written completely (is the disk full?)");
  }
}

}  // namespace kerf
