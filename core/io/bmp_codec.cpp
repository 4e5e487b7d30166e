#include "io/bmp_codec.hpp"

#include <stb_image.h>

#include <cstdio>
#include <memory>

#include "util/error.hpp"

namespace kerf {
namespace {

std::string reason() {
  const char* why = stbi_failure_reason();
  return why ? why : "unknown error";
}

}  // namespace

bool hasBmpSignature(const std::filesystem::path& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  char signature[2] = {};
  return file && std::fread(signature, 1, 2, file.get()) == 2 && signature[0] == 'B' && signature[1] == 'M';
}

BmpHeader readBmpHeader(const std::filesystem::path& path) {
  BmpHeader h;
  if (!stbi_info(path.c_str(), &h.width, &h.height, &h.channels))
    throw InputError("cannot read image " + path.string() + ": " + reason());
  // stb reports palette BMPs as 3 channels and decodes 32-bit ones as 4 only when they carry alpha.
  return h;
}

void readBmpPixels(const std::filesystem::path& path, Image& out) {
  int w = 0, h = 0, channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &w, &h, &channels, 0),
                                                         stbi_image_free);
  if (!pixels) throw InputError("cannot decode image " + path.string() + ": " + reason());
  if (w != out.width || h != out.height || (out.channels != channels && out.channels != 3))
    throw InputError("cannot decode image " + path.string() + ": it changed while being read");
  const std::size_t count = static_cast<std::size_t>(w) * h;
  for (std::size_t p = 0; p < count; ++p)
    for (int c = 0; c < out.channels; ++c) {
      const int source = out.channels == channels || channels >= 3 ? c : 0;
      out.pixels[p * out.channels + c] =
          static_cast<float>(pixels.get()[p * channels + source]) * (1.0f / 255.0f);
    }
}

}  // namespace kerf
