#include "io/image.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

#include "io/atomic_file.hpp"
#include "io/bmp_codec.hpp"
#include "io/input_file.hpp"
#include "io/oiio_module.hpp"
#include "io/png_codec.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

void checkReadable(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError("image not found: " + path.string());
  checkInputFile(path, "image", kMaxImageFileBytes);  // a FIFO or /dev/zero must not block or feed us
}

// Who decodes a file: chosen by its first bytes, not its extension.
enum class Codec { Png, Bmp, OpenImageIO };

struct Header {
  int width = 0, height = 0, channels = 0;
  Codec codec = Codec::OpenImageIO;
};

Header readHeader(const std::filesystem::path& path) {
  checkReadable(path);
  if (hasPngSignature(path)) {
    const PngHeader png = readPngHeader(path);
    return {png.width, png.height, png.channels, Codec::Png};
  }
  if (hasBmpSignature(path)) {
    const BmpHeader bmp = readBmpHeader(path);
    return {bmp.width, bmp.height, bmp.channels, Codec::Bmp};
  }
  OiioHeader header;
  const std::string error = oiioCodecs(path).readHeader(path.string(), header);
  if (!error.empty()) throw InputError("cannot read image " + path.string() + ": " + error);
  return {header.width, header.height, header.channels, Codec::OpenImageIO};
}

bool hasPngExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".png";
}

// A PNG cut short (an interrupted copy) has no IEND chunk near its end. Refusing it here gives a clear
// message before any decoding.
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
  const Header header = readHeader(path);
  return {header.width, header.height};
}

Image readImage(const std::filesystem::path& path, bool keepChannels) {
  const Header spec = readHeader(path);
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0) {
    throw InputError("image " + path.string() + " is empty");
  }
  const long long pixelCount = static_cast<long long>(spec.width) * spec.height;
  if (pixelCount > kMaxImagePixels) {
    throw InputError("image " + path.string() + " is " + std::to_string(spec.width) + " x " +
                     std::to_string(spec.height) + " pixels; Kerf reads images up to " +
                     std::to_string(kMaxImagePixels / 1'000'000) +
                     " megapixels. Scale the photo down first.");
  }
  if (spec.channels > 16) {
    throw InputError("image " + path.string() + " has " + std::to_string(spec.channels) +
                     " channels; Kerf reads grey, RGB and RGBA images");
  }
  if (spec.codec == Codec::Png) checkPngComplete(path);
  // One float copy of the image is all a read takes (non-RGB images are converted row by row); that
  // copy must fit the memory budget, checked before it is taken.
  const int channels = keepChannels ? spec.channels : 3;
  checkImageReadMemory(path.string(), spec.width, spec.height, channels);
  Image out(spec.width, spec.height, channels);
  if (spec.codec == Codec::Png) {
    readPngPixels(path, out);
    return out;
  }
  if (spec.codec == Codec::Bmp) {
    readBmpPixels(path, out);
    return out;
  }
  std::size_t nonFinite = 0;
  const std::string error = oiioCodecs(path).readPixels(path.string(), out, nonFinite);
  if (!error.empty()) throw InputError("cannot decode image " + path.string() + ": " + error);
  // Float TIFF and EXR photos can hold NaN or infinity; one such pixel spreads through every filter and
  // fit that reads it (it crashed detect). Refused, naming how many, rather than guessed at.
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
    if (hasPngExtension(path)) {
      PngWriteOptions options;
      options.bits = bits == 16 ? 16 : 8;
      writePngFile(temporary, image, options, path);
    } else {
      OiioPage page;
      page.pixels = &image;
      page.type = bits == 16 ? "uint16" : "uint8";
      const std::string error = oiioCodecs(path).writePages(path.string(), temporary.string(), {page});
      if (!error.empty()) throw InputError("cannot write " + path.string() + ": " + error);
    }
    verifyWrittenImage(temporary, path);
  });
}

void verifyWrittenImage(const std::filesystem::path& written, const std::filesystem::path& target) {
  if (!hasPngExtension(written)) return;  // the TIFF and EXR writers report a failed write themselves
  // A complete PNG ends with its IEND chunk: a second guard after the writer's own checks, cheaper than
  // decoding it again.
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
