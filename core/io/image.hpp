#pragma once
// Image files (image/image.hpp): PNG with libpng (io/png_codec.hpp), the rest with OpenImageIO.
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "util/size_limits.hpp"

namespace kerf {

// readImage refuses files over kMaxImagePixels (util/size_limits.hpp) from their header, before any pixel
// memory is taken, so a photo that claims 20000 x 20000 pixels (or a corrupt header) cannot exhaust
// memory. readImageSize does not apply it.

// Reads PNG and any format OpenImageIO knows; converts to float 0..1 with 3 channels (grey is replicated,
// alpha dropped) unless keepChannels. Throws InputError with a message naming the file.
Image readImage(const std::filesystem::path& path, bool keepChannels = false);
// Only the size, without decoding pixels. Throws InputError.
glm::ivec2 readImageSize(const std::filesystem::path& path);

// Writes the image (format from the extension; 8 bits per channel unless bits = 16), atomically:
// a temporary file in the same folder is renamed over the target. Throws InputError.
void writeImage(const std::filesystem::path& path, const Image& image, int bits = 8);

// Checks that an image file just written to `written` is complete before it replaces `target`: a full
// disk or a quota can cut a PNG short without every writer noticing, and a truncated PNG would replace
// a good file. Throws InputError naming `target`.
void verifyWrittenImage(const std::filesystem::path& written, const std::filesystem::path& target);

}  // namespace kerf
