#include "texture/texture_statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace kerf {
namespace {

// Weights of the parts of the style distance. The filter quantiles carry most of the information
// (size, spacing, contrast of pores, rays and fibres); the correlations and colours refine it.
constexpr double kCorrelationWeight = 0.5;
constexpr double kColourWeight = 0.5;
constexpr float kMinSigmaPx = 0.5f;           // finer than this the sampled kernels stop meaning anything
constexpr std::size_t kMinLabelPixels = 256;  // fewer pixels of a label give no statistics of it

cv::Mat luminance(const Image& image) {
  if (image.channels < 3) throw InputError("texture statistics need RGB images");
  cv::Mat grey(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      grey.at<float>(y, x) = 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
    }
  return grey;
}

// Sampled Gaussian and its first and second derivatives (1D, separable), each on [-radius, radius].
struct DerivativeKernels {
  cv::Mat g, d1, d2;
};

DerivativeKernels derivativeKernels(float sigma) {
  const int radius = static_cast<int>(std::ceil(3.0f * sigma)) + 1;
  DerivativeKernels k{cv::Mat(2 * radius + 1, 1, CV_32F), cv::Mat(2 * radius + 1, 1, CV_32F),
                      cv::Mat(2 * radius + 1, 1, CV_32F)};
  double sum = 0;
  for (int i = -radius; i <= radius; ++i) sum += std::exp(-0.5 * i * i / (sigma * sigma));
  double meanD2 = 0;
  for (int i = -radius; i <= radius; ++i) {
    const double x = i, s2 = sigma * sigma;
    const double g = std::exp(-0.5 * x * x / s2) / sum;
    k.g.at<float>(i + radius) = static_cast<float>(g);
    k.d1.at<float>(i + radius) = static_cast<float>(-x / s2 * g);
    k.d2.at<float>(i + radius) = static_cast<float>((x * x / (s2 * s2) - 1.0 / s2) * g);
    meanD2 += (x * x / (s2 * s2) - 1.0 / s2) * g;
  }
  // A second derivative must not respond to a flat image; sampling leaves a small DC term.
  k.d2 -= meanD2 / (2 * radius + 1);
  return k;
}

// The scale-normalised second derivative along angle theta, steered from Ixx, Ixy, Iyy (the G2 basis is
// three-dimensional, so any orientation is a combination of these three).
void orientedResponses(const cv::Mat& grey, float sigma, int orientations, std::vector<cv::Mat>& out) {
  const DerivativeKernels k = derivativeKernels(sigma);
  cv::Mat ixx, iyy, ixy;
  cv::sepFilter2D(grey, ixx, CV_32F, k.d2, k.g, cv::Point(-1, -1), 0, cv::BORDER_REFLECT101);
  cv::sepFilter2D(grey, iyy, CV_32F, k.g, k.d2, cv::Point(-1, -1), 0, cv::BORDER_REFLECT101);
  cv::sepFilter2D(grey, ixy, CV_32F, k.d1, k.d1, cv::Point(-1, -1), 0, cv::BORDER_REFLECT101);
  const float norm = sigma * sigma;
  for (int o = 0; o < orientations; ++o) {
    const double theta = std::numbers::pi * o / orientations;
    const float c = static_cast<float>(std::cos(theta)), s = static_cast<float>(std::sin(theta));
    out.push_back(norm * (c * c * ixx + 2.0f * c * s * ixy + s * s * iyy));
  }
}

// Sorts floats (no NaN) by their bits: an LSD radix sort, 3 passes of 11 bits over keys that order as the
// floats do (the sign bit flipped, negative values inverted). A quantile needs exact order statistics;
// this gives all of them in about 6 n steps, where nth_element from rank to rank took 23 % of a texture
// search and a multi-select of the 30 ranks 25 % (issue 16 item 6).
void radixSort(std::vector<float>& values) {
  const std::size_t n = values.size();
  if (n < 512) {
    std::sort(values.begin(), values.end());
    return;
  }
  std::vector<std::uint32_t> keys(n), other(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t u;
    std::memcpy(&u, &values[i], sizeof u);
    keys[i] = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  }
  for (const int shift : {0, 11, 22}) {
    std::array<std::size_t, 2048> count{};
    for (const std::uint32_t k : keys) ++count[(k >> shift) & 2047u];
    std::size_t sum = 0;
    for (std::size_t& c : count) {
      const std::size_t here = c;
      c = sum;
      sum += here;
    }
    for (const std::uint32_t k : keys) other[count[(k >> shift) & 2047u]++] = k;
    keys.swap(other);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = keys[i];
    const std::uint32_t u = (k & 0x80000000u) ? (k & 0x7fffffffu) : ~k;
    std::memcpy(&values[i], &u, sizeof u);
  }
}

// The values at the `count` quantiles (interpolated between neighbours), as a full sort gives them.
std::vector<double> quantilesOf(std::vector<float>& values, int count) {
  std::vector<double> q(count, 0.0);
  if (values.empty()) return q;
  radixSort(values);
  for (int k = 0; k < count; ++k) {
    const double at = (k + 0.5) / count * (values.size() - 1);
    const auto lo = static_cast<std::size_t>(at);
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    const double low = values[lo];
    q[k] = low + (at - lo) * (double(values[hi]) - low);
  }
  return q;
}

double spreadOf(const std::vector<float>& values) {
  if (values.empty()) return 0;
  double sum = 0, sum2 = 0;
  for (float v : values) sum += v, sum2 += double(v) * v;
  const double mean = sum / values.size();
  return std::sqrt(std::max(0.0, sum2 / values.size() - mean * mean));
}

}  // namespace

namespace {

// Filter responses and colours of a set of pixels, before they are summarised.
struct PixelSamples {
  std::vector<std::vector<float>> responses;  // per channel
  std::array<std::vector<float>, 4> colours;  // R, G, B, luminance
};

TextureStatistics summarise(PixelSamples& samples, int channels, int quantiles) {
  TextureStatistics stats;
  const std::size_t n = samples.responses.empty() ? 0 : samples.responses[0].size();
  if (n == 0) return stats;
  stats.channels = channels;
  std::vector<double> means(channels, 0.0);
  for (int c = 0; c < channels; ++c) {
    stats.filterSpread.push_back(spreadOf(samples.responses[c]));
    for (float v : samples.responses[c]) means[c] += v;
    means[c] /= n;
  }
  // Normalised Gram matrix of the centred responses (before sorting them for the quantiles).
  for (int i = 0; i < channels; ++i)
    for (int j = i + 1; j < channels; ++j) {
      const std::vector<float>&a = samples.responses[i], &b = samples.responses[j];
      double cov = 0;
      for (std::size_t k = 0; k < n; ++k) cov += (a[k] - means[i]) * (b[k] - means[j]);
      cov /= n;
      const double denom = stats.filterSpread[i] * stats.filterSpread[j];
      stats.correlations.push_back(denom > 1e-12 ? cov / denom : 0.0);
    }
  for (int c = 0; c < channels; ++c) {
    const std::vector<double> q = quantilesOf(samples.responses[c], quantiles);
    stats.filterQuantiles.insert(stats.filterQuantiles.end(), q.begin(), q.end());
  }
  stats.luminanceSpread = spreadOf(samples.colours[3]);
  for (auto& channel : samples.colours) {
    const std::vector<double> q = quantilesOf(channel, quantiles);
    stats.colourQuantiles.insert(stats.colourQuantiles.end(), q.begin(), q.end());
  }
  return stats;
}

}  // namespace

std::vector<TextureStatistics> computeLabelledTextureStatistics(
    std::span<const Image> crops, std::span<const std::vector<std::uint8_t>> labels, int labelCount,
    float pxPerMm, const TextureStatisticsOptions& options) {
  if (!(pxPerMm > 0.0f)) throw InputError("texture statistics need a positive px/mm");
  if (!labels.empty() && labels.size() != crops.size())
    throw InputError("texture statistics: one label map per crop");
  const int scales = static_cast<int>(options.scalesMm.size());
  const int channels = scales * options.orientations;
  float largestSigma = kMinSigmaPx;
  for (float mm : options.scalesMm) largestSigma = std::max(largestSigma, mm * pxPerMm);
  // Pixels near a crop's edge see the reflected border at the coarse scales: leave them out.
  const int border = static_cast<int>(std::ceil(2.0f * largestSigma));

  std::vector<PixelSamples> groups(1 + std::max(0, labelCount));  // all pixels, then one per label
  for (PixelSamples& g : groups) g.responses.resize(channels);
  std::vector<cv::Mat> bank;
  for (std::size_t k = 0; k < crops.size(); ++k) {
    const Image& crop = crops[k];
    if (crop.empty()) continue;
    const cv::Mat grey = luminance(crop);
    bank.clear();
    for (float mm : options.scalesMm)
      orientedResponses(grey, std::max(kMinSigmaPx, mm * pxPerMm), options.orientations, bank);
    const int b = (crop.width > 2 * border + 4 && crop.height > 2 * border + 4) ? border : 0;
    for (int y = b; y < crop.height - b; ++y)
      for (int x = b; x < crop.width - b; ++x) {
        const auto add = [&](PixelSamples& g) {
          for (int c = 0; c < channels; ++c) g.responses[c].push_back(bank[c].at<float>(y, x));
          const float* p = crop.pixel(x, y);
          for (int i = 0; i < 3; ++i) g.colours[i].push_back(p[i]);
          g.colours[3].push_back(grey.at<float>(y, x));
        };
        add(groups[0]);
        if (labels.empty()) continue;
        const std::uint8_t label = labels[k][static_cast<std::size_t>(y) * crop.width + x];
        if (label < labelCount) add(groups[1 + label]);
      }
  }
  if (groups[0].responses.empty() || groups[0].responses[0].empty())
    throw InputError("texture statistics of no pixels");
  std::vector<TextureStatistics> out;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::size_t n = groups[g].responses[0].size();
    out.push_back(g == 0 || n >= kMinLabelPixels ? summarise(groups[g], channels, options.quantiles)
                                                 : TextureStatistics{});
  }
  return out;
}

TextureStatistics computeTextureStatistics(std::span<const Image> crops, float pxPerMm,
                                           const TextureStatisticsOptions& options) {
  return computeLabelledTextureStatistics(crops, {}, 0, pxPerMm, options)[0];
}

StyleDistance styleDistance(const TextureStatistics& texture, const TextureStatistics& target) {
  if (texture.empty() || target.empty()) return {};
  if (texture.channels != target.channels ||
      texture.filterQuantiles.size() != target.filterQuantiles.size() ||
      texture.colourQuantiles.size() != target.colourQuantiles.size())
    throw InputError("texture statistics computed with different options cannot be compared");
  StyleDistance d;
  const int channels = target.channels;
  const std::size_t q = target.filterQuantiles.size() / std::max(1, channels);
  for (int c = 0; c < channels; ++c) {
    double sum = 0;
    for (std::size_t k = 0; k < q; ++k)
      sum += std::abs(texture.filterQuantiles[c * q + k] - target.filterQuantiles[c * q + k]);
    d.filters += sum / q / (target.filterSpread[c] + 1e-4);
  }
  d.filters /= std::max(1, channels);
  for (std::size_t i = 0; i < target.correlations.size(); ++i)
    d.correlations += std::abs(texture.correlations[i] - target.correlations[i]);
  if (!target.correlations.empty()) d.correlations /= target.correlations.size();
  for (std::size_t i = 0; i < target.colourQuantiles.size(); ++i)
    d.colours += std::abs(texture.colourQuantiles[i] - target.colourQuantiles[i]);
  if (!target.colourQuantiles.empty())
    d.colours /= target.colourQuantiles.size() * (target.luminanceSpread + 1e-3);
  d.total = d.filters + kCorrelationWeight * d.correlations + kColourWeight * d.colours;
  return d;
}

}  // namespace kerf
