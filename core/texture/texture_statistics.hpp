#pragma once
// Texture statistics ("style") of face images, and a distance between them, for inferring the detail
// of the wood texture (pores, rays, fibres) from photos (Mokume Sec. 5.3.1 / A.2.3). The authors
// compare VGG features; no network weights can be downloaded here, so Kerf uses the classic
// hand-built alternative (Heeger & Bergen 1995, Portilla & Simoncelli 2000): the responses of a fixed
// multi-scale oriented filter bank, described by their marginal distributions (quantiles) and their
// normalised cross-correlations (a Gram matrix), plus the distribution of the colours. Why this bank:
// - second derivatives of a Gaussian respond to dark dots (pores seen end-on) and to dark or light
//   lines (pores and fibres seen along the grain, rays, latewood edges) of a width set by the scale;
// - the scales are given in millimetres and converted with the image's px/mm, so a photo and a
//   rendering compare at true scale: a pore twice as large lands in the next scale's channel;
// - four orientations tell end grain (isotropic dots) from side grain (streaks along the fibres);
// - quantiles of a response (a 1D Wasserstein distance, as in the sliced-Wasserstein texture loss of
//   Heitz et al. 2021) capture its energy and its sparsity (few large pores vs many small ones).
// Everything is deterministic and needs only OpenCV.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "io/image.hpp"

namespace kerf {

struct TextureStatisticsOptions {
  // Gaussian sigmas of the filter bank, in mm on the wood (converted with px/mm).
  std::vector<float> scalesMm{0.08f, 0.16f, 0.32f, 0.64f};
  int orientations = 4;  // second-derivative directions, evenly over 180 degrees
  int quantiles = 15;    // of each filter response and colour channel, at (k + 0.5) / quantiles
};

// Statistics of one face: several crops of it pooled.
struct TextureStatistics {
  int channels = 0;  // filter channels = scales x orientations
  // quantiles[c * q + k]: k-th quantile of channel c (responses scale-normalised by sigma^2).
  std::vector<double> filterQuantiles;
  std::vector<double> filterSpread;  // standard deviation of each channel
  // Normalised cross-correlations of the channels (upper triangle, row-major, no diagonal).
  std::vector<double> correlations;
  // Quantiles of R, G, B (0..1) and of the luminance, 4 x q values.
  std::vector<double> colourQuantiles;
  double luminanceSpread = 0;  // standard deviation of the luminance

  bool empty() const { return channels == 0; }
};

// Pools every crop (RGB, 0..1) of one face, imaged at pxPerMm. Crops may differ in size.
TextureStatistics computeTextureStatistics(std::span<const Image> crops, float pxPerMm,
                                           const TextureStatisticsOptions& options = {});

// The statistics of all pixels (first) and then of the pixels of each label 0..labelCount-1, for crops
// with one label per pixel (row-major, the crop's size; labels >= labelCount: none), e.g. the ring phase
// where each pixel lies. A label held by fewer than 256 pixels gives empty statistics.
std::vector<TextureStatistics> computeLabelledTextureStatistics(
    std::span<const Image> crops, std::span<const std::vector<std::uint8_t>> labels, int labelCount,
    float pxPerMm, const TextureStatisticsOptions& options = {});

// How far a texture is from a target texture, by part. Each part is normalised by the target's spread
// (so it is unitless and asymmetric: `target` sets the scale).
struct StyleDistance {
  double filters = 0;       // mean over channels of the quantile distance / target spread
  double correlations = 0;  // mean |difference| of the normalised cross-correlations
  double colours = 0;       // mean colour-quantile distance / target luminance spread
  double total = 0;         // filters + correlations + colours weighted (see styleDistance)
};
// All zero when either is empty.
StyleDistance styleDistance(const TextureStatistics& texture, const TextureStatistics& target);

}  // namespace kerf
