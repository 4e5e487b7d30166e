#include "util/size_limits.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "util/error.hpp"

namespace kerf {
namespace {

std::string gib(std::uint64_t bytes) {
  std::ostringstream s;
  s.precision(bytes >= (10ull << 30) ? 0 : 1);
  s << std::fixed << bytes / double(1ull << 30) << " GiB";
  return s.str();
}

// cgroup v2 (containers, systemd slices): "max" or a byte count.
std::uint64_t cgroupLimit() {
  std::ifstream file("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(file >> text) || text == "max") return UINT64_MAX;
  try {
    return std::stoull(text);
  } catch (const std::exception&) {
    return UINT64_MAX;
  }
}

}  // namespace

void checkImageSize(glm::ivec2 size, std::string_view what, float pxPerMm) {
  const long long pixels = static_cast<long long>(size.x) * size.y;
  if (size.x >= 1 && size.y >= 1 && size.x <= kMaxImageSide && size.y <= kMaxImageSide &&
      pixels <= kMaxImagePixels)
    return;
  std::ostringstream s;
  s << what << " would be " << size.x << " x " << size.y << " px";
  if (size.x < 1 || size.y < 1) {
    s << ": an image needs at least one pixel each way";
    throw InputError(s.str());
  }
  s.precision(3);
  s << " (" << pixels / 1e6 << " megapixels); Kerf makes images of up to " << kMaxImagePixels / 1'000'000
    << " megapixels and " << kMaxImageSide << " px a side";
  if (pxPerMm > 0.0f) {
    const double scale = std::min({std::sqrt(double(kMaxImagePixels) / double(pixels)),
                                   double(kMaxImageSide) / size.x, double(kMaxImageSide) / size.y});
    s.precision(6);
    s << ": use at most " << std::floor(pxPerMm * scale * 100.0) / 100.0 << " px/mm";
  } else {
    s << ": lower the resolution";
  }
  throw InputError(s.str());
}

std::uint64_t usableMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  std::uint64_t bytes =
      pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 8ull << 30;
  bytes = std::min(bytes, cgroupLimit());
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = std::min<std::uint64_t>(bytes, limit.rlim_cur);
  return bytes;
}

void checkMemoryNeed(std::uint64_t bytes, std::string_view what) {
  const std::uint64_t usable = usableMemoryBytes();
  if (bytes <= usable / 10 * 8) return;
  throw InputError(std::string(what) + " needs about " + gib(bytes) +
                   " of memory; this machine lets Kerf use " + gib(usable) + ": lower the resolution");
}

void checkImageReadMemory(const std::string& file, int width, int height, int channels,
                          std::uint64_t usable) {
  const std::uint64_t pixels = std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0));
  const std::uint64_t need = pixels * std::uint64_t(std::max(channels, 1)) * sizeof(float);
  const std::uint64_t budget = usable / 10 * 8;
  if (need <= budget) return;
  std::ostringstream s;
  s.precision(4);
  s << "image " << file << " is " << width << " x " << height << " px (" << pixels / 1e6
    << " megapixels): reading it takes " << gib(need) << " of memory (" << channels
    << " float channels a pixel) and Kerf's budget for it is " << gib(budget) << " (80 % of the "
    << gib(usable) << " this machine lets Kerf use); scale the image down first";
  throw InputError(s.str());
}

}  // namespace kerf
