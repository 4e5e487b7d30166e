#include "io/png_bytes.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "util/error.hpp"

namespace kerf {

std::vector<unsigned char> encodePng(const Image& image) {
  if (image.empty()) throw InputError("cannot encode an empty image as PNG");
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create("memory.png", &proxy);
  if (!out) throw InputError("cannot encode PNG: " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
  if (!out->open("memory.png", spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) ||
      !out->close())
    throw InputError("cannot encode PNG: " + out->geterror());
  return bytes;
}

}  // namespace kerf
