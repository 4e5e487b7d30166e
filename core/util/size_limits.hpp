#pragma once
// Bounds on the memory a parameter can make Kerf take (issue 8: "a bounded memory use for big inputs").
// Files are bounded by their size or, for images, by their header (io/image.hpp); these bound what a
// resolution option asks for: the images Kerf renders and the volumes it keeps whole. Each throws
// InputError before any of that memory is taken, saying what was asked and what the bound allows.
#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <string_view>

namespace kerf {

// The largest image Kerf reads or makes: 120 megapixels (a 100 MP camera's photo; about 1.4 GB as float
// RGB). Kerf checks every image it writes by reading it back, so it never makes one it could not read.
inline constexpr long long kMaxImagePixels = 120'000'000;
// The longest side of an image Kerf makes (JPEG's limit; a 6.5 m board at 10 px/mm).
inline constexpr int kMaxImageSide = 65'535;

// A pixel count from a length in mm times px/mm, at least 1, saturated instead of overflowing an int (a
// huge block or resolution then fails checkImageSize with its size instead of wrapping round).
inline int pixelsAlong(double pixels) {
  return pixels >= 1.0 ? (pixels < 2e9 ? static_cast<int>(pixels) : 2'000'000'000) : 1;
}

// Throws unless an image of `size` px may be made. `what` names it ("the image of face A"); when
// pxPerMm > 0 the message gives the largest resolution that would do.
void checkImageSize(glm::ivec2 size, std::string_view what, float pxPerMm = 0.0f);

// The memory this process may use: the machine's physical memory, lowered by a cgroup's memory.max or
// an address-space rlimit where one is set.
std::uint64_t usableMemoryBytes();

// Throws when `bytes` exceed 80 % of usableMemoryBytes(), so that a big request fails with a message
// instead of swapping the machine or being killed. `what` names the request ("the VDB volume").
void checkMemoryNeed(std::uint64_t bytes, std::string_view what);

// Throws, naming `file`, its size in pixels and the budget, unless one float copy of a width x height
// image of `channels` channels (what io/image.cpp's readImage takes) fits 80 % of `usable` bytes.
void checkImageReadMemory(const std::string& file, int width, int height, int channels,
                          std::uint64_t usable = usableMemoryBytes());

}  // namespace kerf
