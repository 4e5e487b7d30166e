#include "fit/ring_band_profile.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace kerf {

void RingBandProfile::add(const RingBandProfile& other) {
  if (darkSum.empty()) {
    *this = other;
    return;
  }
  for (std::size_t b = 0; b < darkSum.size() && b < other.darkSum.size(); ++b) {
    darkSum[b] += other.darkSum[b];
    pixels[b] += other.pixels[b];
  }
}

std::vector<double> RingBandProfile::shape() const {
  std::vector<double> mean(darkSum.size());
  double total = 0;
  for (std::size_t b = 0; b < darkSum.size(); ++b) {
    if (pixels[b] <= 0) return {};
    mean[b] = darkSum[b] / pixels[b];
    total += mean[b];
  }
  // Below 1e-5 of the luminance per pixel it is the blurs' rounding, not detail.
  if (mean.empty() || !(total > 1e-5 * static_cast<double>(mean.size()))) return {};
  for (double& m : mean) m *= static_cast<double>(mean.size()) / total;
  return mean;
}

RingBandProfile ringBandProfile(const Image& crop, std::span<const std::uint8_t> labels, int bins,
                                double pxPerMm) {
  if (crop.channels < 3) throw InputError("ring band profile: a colour image is needed");
  if (labels.size() != static_cast<std::size_t>(crop.width) * crop.height)
    throw InputError("ring band profile: one ring-phase label per pixel is needed");
  cv::Mat lum(crop.height, crop.width, CV_32F);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      const float* p = crop.pixel(x, y);
      lum.at<float>(y, x) = 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
    }
  // A pore is a hole of 1-3 px at Mokume's 6.4 px/mm: the luminance after a blur that keeps it (sensor noise
  // out) against the surroundings within ~0.5 mm.
  const double scale = pxPerMm / 6.4;
  cv::Mat fine, around;
  cv::GaussianBlur(lum, fine, cv::Size(), 0.7 * scale, 0.7 * scale, cv::BORDER_REFLECT101);
  cv::GaussianBlur(lum, around, cv::Size(), 3.0 * scale, 3.0 * scale, cv::BORDER_REFLECT101);
  RingBandProfile profile;
  profile.darkSum.assign(bins, 0.0);
  profile.pixels.assign(bins, 0.0);
  const int margin = std::min({static_cast<int>(std::ceil(9.0 * scale)), crop.width / 4, crop.height / 4});
  for (int y = margin; y < crop.height - margin; ++y)
    for (int x = margin; x < crop.width - margin; ++x) {
      const int b = labels[static_cast<std::size_t>(y) * crop.width + x];
      if (b >= bins) continue;
      profile.darkSum[b] += std::max(0.0f, around.at<float>(y, x) - fine.at<float>(y, x));
      profile.pixels[b] += 1.0;
    }
  return profile;
}

double ringBandDifference(const RingBandProfile& render, const RingBandProfile& photo) {
  const std::vector<double> b = photo.shape();
  if (b.empty()) return 0.0;
  std::vector<double> a = render.shape();
  if (a.size() != b.size()) a.assign(b.size(), 1.0);  // no dark detail at all: spread evenly (as nothing is)
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
  return sum / static_cast<double>(a.size());
}

}  // namespace kerf
