#include "fit/pore_band_side.hpp"

#include <algorithm>
#include <cmath>

#include "fit/ring_band_profile.hpp"
#include "util/parallel.hpp"

namespace kerf {

bool isRingPorous(const WoodParameters& params) {
  return params.poreRadiusEarly >= 0.05f && params.poreRadiusEarly > 3.0f * params.poreRadiusLate;
}

namespace {

// The photos' dark detail per 1/bins of the ring phase, over the mean (ring_band_profile.hpp).
std::vector<double> darkDetailByPhase(const GrowthField& field, float ringOffset, const Block& block,
                                      const std::array<Image, 6>& photos, int kBins) {
  RingBandProfile total;
  for (FaceId face : kAllFaces) {
    const Image& photo = photos[faceIndex(face)];
    if (photo.empty() || photo.channels < 3) continue;
    const glm::ivec2 size(photo.width, photo.height);
    std::vector<std::uint8_t> labels(static_cast<std::size_t>(photo.width) * photo.height);
    parallelRows(photo.height, [&](int y) {
      for (int x = 0; x < photo.width; ++x) {
        const float t = field.evaluate(block.pixelCenter(face, x, y, size)) - ringOffset;
        const float phase = t - std::floor(t);
        labels[static_cast<std::size_t>(y) * photo.width + x] =
            static_cast<std::uint8_t>(std::clamp(static_cast<int>(phase * kBins), 0, kBins - 1));
      }
    });
    const double pxPerMm = photo.width / static_cast<double>(block.faceImageSize(face, 1.0f).x);
    total.add(ringBandProfile(photo, labels, kBins, pxPerMm));
  }
  return total.shape();
}

}  // namespace

PoreBandPlacement poreBandPlacement(const GrowthField& field, float ringOffset, const Block& block,
                                    const std::array<Image, 6>& photos) {
  constexpr int kBins = 10;
  PoreBandPlacement placement;
  placement.shape = darkDetailByPhase(field, ringOffset, block, photos, kBins);
  if (placement.shape.size() == kBins) {
    const auto& s = placement.shape;
    placement.earlyMinusLate = (s[0] + s[1] + s[2]) / 3.0 - (s[7] + s[8] + s[9]) / 3.0;
  }
  return placement;
}

std::optional<double> poreBandStart(const GrowthField& field, float ringOffset, const Block& block,
                                    const std::array<Image, 6>& photos, double bandShare) {
  constexpr int kBins = 40;
  const std::vector<double> shape = darkDetailByPhase(field, ringOffset, block, photos, kBins);
  if (shape.size() != kBins) return std::nullopt;
  const int width = std::clamp(static_cast<int>(std::lround(bandShare * kBins)), 1, kBins - 1);
  int best = 0;
  double bestSum = -1e300;
  for (int start = 0; start < kBins; ++start) {  // circular: a band may straddle the ring line
    double sum = 0;
    for (int i = 0; i < width; ++i) sum += shape[(start + i) % kBins];
    if (sum > bestSum) bestSum = sum, best = start;
  }
  const double phase = static_cast<double>(best) / kBins;
  return phase >= 0.5 ? phase - 1.0 : phase;
}

}  // namespace kerf
