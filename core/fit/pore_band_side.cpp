#include "fit/pore_band_side.hpp"

#include <algorithm>
#include <cmath>

#include "fit/ring_band_profile.hpp"
#include "util/parallel.hpp"

namespace kerf {

bool isRingPorous(const WoodParameters& params) {
  return params.poreRadiusEarly >= 0.05f && params.poreRadiusEarly > 3.0f * params.poreRadiusLate;
}

PoreBandPlacement poreBandPlacement(const GrowthField& field, float ringOffset, const Block& block,
                                    const std::array<Image, 6>& photos) {
  constexpr int kBins = 10;
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
  PoreBandPlacement placement;
  placement.shape = total.shape();
  if (placement.shape.size() == kBins) {
    const auto& s = placement.shape;
    placement.earlyMinusLate = (s[0] + s[1] + s[2]) / 3.0 - (s[7] + s[8] + s[9]) / 3.0;
  }
  return placement;
}

}  // namespace kerf
