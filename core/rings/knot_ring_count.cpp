#include "rings/knot_ring_count.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>

#include "rings/annotations.hpp"

namespace kerf {

namespace {

float pixelLuminance(const Image& photo, int x, int y) {
  const float* p = photo.pixel(x, y);
  return photo.channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
}

// Luminance at a continuous image position (pixel centres at +0.5), bilinear; false off the photo.
bool luminanceAt(const Image& photo, float x, float y, float& out) {
  const float fx = x - 0.5f, fy = y - 0.5f;
  if (!(fx >= 0.0f && fy >= 0.0f && fx <= static_cast<float>(photo.width - 1) &&
        fy <= static_cast<float>(photo.height - 1)))
    return false;
  const int x0 = std::min(static_cast<int>(fx), photo.width - 2 < 0 ? 0 : photo.width - 2);
  const int y0 = std::min(static_cast<int>(fy), photo.height - 2 < 0 ? 0 : photo.height - 2);
  const int x1 = std::min(x0 + 1, photo.width - 1), y1 = std::min(y0 + 1, photo.height - 1);
  const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
  const auto lum = [&](int px, int py) { return pixelLuminance(photo, px, py); };
  out = (1 - ty) * ((1 - tx) * lum(x0, y0) + tx * lum(x1, y0)) +
        ty * ((1 - tx) * lum(x0, y1) + tx * lum(x1, y1));
  return true;
}

// The ellipse's radius (mm) in the direction `angle` (face mm, from x towards y).
float ellipseRadius(const KnotOutline& o, float angle) {
  const float c = std::cos(angle - o.angleRad) / std::max(o.semiAxesMm.x, 1e-3f);
  const float s = std::sin(angle - o.angleRad) / std::max(o.semiAxesMm.y, 1e-3f);
  return 1.0f / std::sqrt(c * c + s * s);
}

std::string fixed(double v, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

}  // namespace

KnotRingCount countKnotRings(const Image& photo, const Block& block, const KnotOutline& outline,
                             const KnotRingCountOptions& options) {
  KnotRingCount out;
  out.knot = outline.knot;
  out.face = outline.face;
  if (!outline.found) {
    out.note = "no outline of the knot on this face";
    return out;
  }
  if (photo.empty()) {
    out.note = "no photo of the face";
    return out;
  }
  const glm::ivec2 size(photo.width, photo.height);
  const glm::vec2 pxPerMm = glm::vec2(size) / faceSizeMm(block, outline.face);
  const float pi = std::numbers::pi_v<float>;
  const float span = options.outer - options.inner;

  // The shortest ray, in photo pixels, bounds the finest countable rings; the longest sets the samples.
  float shortestPx = 1e30f, longestPx = 0.0f;
  std::vector<float> rayAngle(options.rays), rayMm(options.rays);
  for (int a = 0; a < options.rays; ++a) {
    rayAngle[a] = 2.0f * pi * (static_cast<float>(a) + 0.5f) / static_cast<float>(options.rays);
    rayMm[a] = ellipseRadius(outline, rayAngle[a]);
    const glm::vec2 px = rayMm[a] * glm::vec2(std::cos(rayAngle[a]), std::sin(rayAngle[a])) * pxPerMm;
    shortestPx = std::min(shortestPx, glm::length(px));
    longestPx = std::max(longestPx, glm::length(px));
  }
  const float maxRings = shortestPx / options.minLinePx;
  if (maxRings < options.minRings + 1.0f) {
    out.note =
        "the knot is too small on this photo to count its rings (" + fixed(2 * shortestPx, 0) + " px across)";
    return out;
  }
  // The camera's noise (and the wood's finest texture): the pixels' robust deviation from the mean of
  // their four neighbours over the whole photo, mostly plain wood (1.48 MAD / sqrt(1.25) for white noise).
  std::vector<float> deviations;
  deviations.reserve(static_cast<std::size_t>(photo.width) * photo.height);
  const auto lum = [&](int x, int y) { return pixelLuminance(photo, x, y); };
  for (int y = 1; y + 1 < photo.height; ++y)
    for (int x = 1; x + 1 < photo.width; ++x)
      deviations.push_back(
          std::abs(lum(x, y) - 0.25f * (lum(x - 1, y) + lum(x + 1, y) + lum(x, y - 1) + lum(x, y + 1))));
  if (deviations.empty()) {
    out.note = "the photo is too small";
    return out;
  }
  std::nth_element(deviations.begin(),
                   deviations.begin() + static_cast<std::ptrdiff_t>(deviations.size() / 2), deviations.end());
  const float photoNoise = 1.4826f * deviations[deviations.size() / 2] / std::sqrt(1.25f);

  // Each ray sampled every half pixel between `inner` and `outer`, lightly smoothed (smoothPx) against the
  // camera's noise; its rings are its dark lines (latewood, or the dark band of a smooth profile): local
  // minima deeper than the noise by a margin, at least minLinePx apart.
  const int sectors = std::max(2, options.sectors);
  std::vector<double> sectorSum(sectors, 0.0), rayRings;
  std::vector<int> sectorRays(sectors, 0);
  std::vector<float> depths;
  // All rays on one grid of u (as finely as the longest ray needs), so that each can be averaged with its
  // neighbours: the rings are concentric, at the same u on neighbouring rays, where pores, fibres and
  // specks are not (a pore is a dip on one ray only).
  const int n = std::max(8, static_cast<int>(std::ceil(2.0f * span * longestPx)));
  std::vector<std::vector<float>> rays(options.rays);
  for (int a = 0; a < options.rays; ++a) {
    const glm::vec2 dir(std::cos(rayAngle[a]), std::sin(rayAngle[a]));
    std::vector<float> raw(n);
    bool inside = true;
    for (int j = 0; j < n && inside; ++j) {
      const float u = options.inner + span * (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
      const glm::vec2 px = faceMmToImage(block, outline.face, outline.center + u * rayMm[a] * dir, size);
      inside = luminanceAt(photo, px.x, px.y, raw[j]);
    }
    if (inside) rays[a] = std::move(raw);  // empty: the ray leaves the photo
  }
  int usedRays = 0;
  for (int a = 0; a < options.rays; ++a) {
    if (rays[a].empty()) continue;
    // The median of the ray and its neighbours at each u: a pore or speck on a few of them drops out.
    std::vector<float> raw(n), column;
    for (int j = 0; j < n; ++j) {
      column.clear();
      for (int b = -options.neighbourRays; b <= options.neighbourRays; ++b) {
        const std::vector<float>& other = rays[(a + b + options.rays) % options.rays];
        if (!other.empty()) column.push_back(other[j]);
      }
      std::nth_element(column.begin(), column.begin() + static_cast<std::ptrdiff_t>(column.size() / 2),
                       column.end());
      raw[j] = column[column.size() / 2];
    }
    const float lengthPx =
        span * glm::length(rayMm[a] * glm::vec2(std::cos(rayAngle[a]), std::sin(rayAngle[a])) * pxPerMm);
    const float step = lengthPx / static_cast<float>(n);  // px per sample
    const int half = std::max(1, static_cast<int>(std::ceil(2.0f * options.smoothPx / step)));
    std::vector<float> smooth(n);
    for (int j = 0; j < n; ++j) {
      double sum = 0, weight = 0;
      for (int i = std::max(0, j - half); i <= std::min(n - 1, j + half); ++i) {
        const double d = (i - j) * step / options.smoothPx;
        const double w = std::exp(-0.5 * d * d);
        sum += w * raw[i], weight += w;
      }
      smooth[j] = static_cast<float>(sum / weight);
    }
    // What is left of the camera's noise after the bilinear samples' smoothing (measured: about 0.6).
    const float noise = 0.6f * photoNoise;
    const float minDepth = std::max(options.minDepth, options.depthOverNoise * noise);
    const int window = std::max(1, static_cast<int>(std::lround(2.0f * options.minLinePx / step)));
    const int apart = std::max(1, static_cast<int>(std::lround(options.minLinePx / step)));
    int dips = 0, last = -apart;
    float firstU = 0, lastU = 0;
    for (int j = 1; j + 1 < n; ++j) {
      if (!(smooth[j] <= smooth[j - 1] && smooth[j] < smooth[j + 1])) continue;
      float left = smooth[j], right = smooth[j];
      for (int i = std::max(0, j - window); i < j; ++i) left = std::max(left, smooth[i]);
      for (int i = j + 1; i <= std::min(n - 1, j + window); ++i) right = std::max(right, smooth[i]);
      const float depth = std::min(left, right) - smooth[j];
      if (depth < minDepth || j - last < apart) continue;
      ++dips;
      last = j;
      const float u = options.inner + span * (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
      if (dips == 1) firstU = u;
      lastU = u;
      depths.push_back(depth / std::max(noise, 1e-4f));
    }
    ++usedRays;
    // Rings per unit of the radius from the first to the last dark line: the count of lines in a fixed
    // window would come in whole numbers (every ray of concentric rings sees the same ones).
    if (dips < 3 || !(lastU > firstU)) continue;
    const double rings = (dips - 1) / static_cast<double>(lastU - firstU);
    rayRings.push_back(rings);
    out.spans.push_back({rayAngle[a], firstU, lastU, dips});
    sectorSum[a * sectors / options.rays] += rings;
    ++sectorRays[a * sectors / options.rays];
  }
  if (usedRays < options.rays / 2) {
    out.note = "the knot runs off the photo: " + std::to_string(usedRays) + " of " +
               std::to_string(options.rays) + " rays inside it";
    return out;
  }
  if (rayRings.size() < static_cast<std::size_t>(usedRays) / 2) {
    out.note = "no rings seen inside the knot: three dark lines or more on " +
               std::to_string(rayRings.size()) + " of " + std::to_string(usedRays) + " rays only";
    return out;
  }
  double rings = 0;
  for (double r : rayRings) rings += r;
  rings /= static_cast<double>(rayRings.size());
  std::vector<double> means;
  for (int k = 0; k < sectors; ++k)
    if (sectorRays[k] > 0) means.push_back(sectorSum[k] / sectorRays[k]);
  double var = 0;
  for (double m : means) var += (m - rings) * (m - rings);
  const double sigma = means.size() > 1 ? std::sqrt(var / (means.size() - 1) / means.size()) : 1e30;
  if (!depths.empty()) {
    std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2),
                     depths.end());
    out.lineContrast = depths[depths.size() / 2];
  }
  out.rings = static_cast<float>(rings);
  out.sigma = static_cast<float>(sigma);
  out.pxPerRing = rings > 0 ? static_cast<float>(shortestPx / rings) : 0.0f;
  const std::string what = fixed(rings, 1) + " +- " + fixed(std::min(sigma, 99.0), 1) +
                           " rings (dark lines " + fixed(out.lineContrast, 1) + "x the noise, " +
                           fixed(out.pxPerRing, 1) + " px apart on the shortest ray)";
  if (rings < options.minRings) {
    out.note = "no rings seen inside the knot: " + what;
    return out;
  }
  if (out.pxPerRing < options.minPxPerRing) {
    out.note = "the knot's rings are too close on this photo to count reliably: " + what;
    return out;
  }
  if (!(sigma <= options.maxRelativeSigma * rings)) {
    out.note = "no rings seen inside the knot: its sectors disagree, " + what;
    return out;
  }
  out.found = true;
  out.note = what;
  return out;
}

}  // namespace kerf
