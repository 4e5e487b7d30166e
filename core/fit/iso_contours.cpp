#include "fit/iso_contours.hpp"

#include "rings/contours.hpp"

#include <algorithm>
#include <cmath>

#include "io/image.hpp"
#include "util/error.hpp"

namespace kerf {

GrayImage8 readRingLocalizationImage(const std::filesystem::path& path) {
  // Kerf's image reader (OpenImageIO) gives floats 0..1; 8-bit values come back exactly by rounding.
  const Image raw = readImage(path, /*keepChannels=*/true);
  GrayImage8 image;
  image.width = raw.width, image.height = raw.height;
  image.pixels.resize(static_cast<std::size_t>(raw.width) * raw.height);
  for (int y = 0; y < raw.height; ++y)
    for (int x = 0; x < raw.width; ++x) {
      const float v = std::clamp(raw.pixel(x, y)[0], 0.0f, 1.0f);  // first channel (red), as the authors
      image.pixels[static_cast<std::size_t>(y) * raw.width + x] =
          static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }
  return image;
}

std::filesystem::path findRingLocalizationImage(const std::filesystem::path& folder, FaceId face) {
  const std::string prefix = std::string(1, faceLetter(face)) + "_arl";
  const std::filesystem::path preferred = folder / (prefix + "-unet.png");
  if (std::filesystem::exists(preferred)) return preferred;
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind(prefix, 0) == 0 && entry.path().extension() == ".png")
      found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());  // a stable choice
  return found.empty() ? std::filesystem::path() : found.front();
}

std::vector<std::vector<glm::ivec2>> extractIsoContours(const GrayImage8& image,
                                                        const ContourExtractionOptions& options) {
  // One implementation of the authors' extraction: core/rings/contours (this keeps the fit's
  // 8-bit interface; g/255 quantises back to g there).
  std::vector<std::vector<glm::ivec2>> result;
  if (image.empty()) return result;
  Image arl(image.width, image.height, 1);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) arl.pixels[i] = image.pixels[i] / 255.0f;
  ContourOptions ringOptions;
  ringOptions.threshold8 = options.threshold;
  ringOptions.margin = options.borderMarginPx;
  ringOptions.minPoints = options.minPoints;
  for (FaceContour& contour : extractContours(arl, FaceId::A, ringOptions))
    result.push_back(std::move(contour.pixels));
  return result;
}

}  // namespace kerf
