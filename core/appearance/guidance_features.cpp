#include "appearance/guidance_features.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "render/wood_model.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
// The grain direction is that of the grain tensor averaged with a Gaussian of this sigma.
constexpr float kGrainScaleMm = 0.8f;
// From this many pixels per mm (2 pixels: 0.17 mm and less) the field is evaluated at every other pixel.
// Mokume's photos (6.4 px/mm) are evaluated at every pixel.
constexpr float kInterpolatedPxPerMm = 12.0f;
// A Gaussian wider than this (pixels) is applied at a coarser resolution (the tensor it averages varies
// over millimetres, and the full-resolution kernel over 1M pixels costs more than the field).
constexpr double kLargestDirectSigma = 8.0;

float smoothStep(float a, float b, float x) {
  if (b <= a) return x < a ? 0.0f : 1.0f;
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

SurfaceGuidance computeGuidance(const WoodModel& model, const SurfaceGrid& grid,
                                const GuidanceWeights& weights, const Progress& progress) {
  const int w = grid.width, h = grid.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  SurfaceGuidance out;
  out.width = w;
  out.height = h;
  out.features.assign(n * kGuidanceChannels, 0.0f);
  out.grainAngle.assign(n, 0.0f);
  out.inside.assign(n, 0);
  // Pass 1: G at every pixel and half a pixel along the normal (its derivative across the surface), the
  // fibre direction. The field extends beyond the block, so pixels outside it still get features and the
  // in-plane derivatives below need no special border.
  std::vector<float> year(n), yearAbove(n), knot(n);
  std::vector<glm::vec3> fibre(n);
  const float stepMm = 0.5f / grid.pxPerMm();
  const Block& block = model.block();
  // On fine grids the field is evaluated at every other pixel of every other row and interpolated
  // (bilinear; the fibre renormalised): it changes over tenths of a millimetre, and its evaluation is most
  // of the guidance's time.
  const int step = grid.pxPerMm() >= kInterpolatedPxPerMm ? 2 : 1;
  const int sw = (w - 1) / step + 1 + (step > 1 && (w - 1) % step != 0 ? 1 : 0);
  const int sh = (h - 1) / step + 1 + (step > 1 && (h - 1) % step != 0 ? 1 : 0);
  auto sampleX = [&](int sx) { return std::min(sx * step, w - 1); };
  auto sampleY = [&](int sy) { return std::min(sy * step, h - 1); };
  std::vector<float> sampledYear(static_cast<std::size_t>(sw) * sh), sampledAbove(sampledYear.size()),
      sampledKnot(sampledYear.size());
  std::vector<glm::vec3> sampledFibre(sampledYear.size());
  parallelRows(
      sh,
      [&](int sy) {
        for (int sx = 0; sx < sw; ++sx) {
          const std::size_t i = static_cast<std::size_t>(sy) * sw + sx;
          const glm::vec3 p = grid.point(float(sampleX(sx)), float(sampleY(sy)));
          // Where the point lies in the tree, without shading it (pores, rays, colour): the same year and
          // fibre as evaluate(), at a fraction of the cost.
          const auto location = model.material().locate(p, true);
          sampledYear[i] = location.year;
          sampledFibre[i] = location.fiberDirection;
          sampledKnot[i] = location.knotDarkness;
          sampledAbove[i] = model.material().year(p + stepMm * grid.normal);
        }
      },
      progress.part(0.0, 0.8));
  parallelRows(h, [&](int y) {
    // The samples around (x, y) and the weights of the second ones.
    auto bracket = [&](int v, int last, auto sample, int& a, int& b, float& t) {
      a = v / step;
      b = std::min(a + 1, last);
      const int from = sample(a), to = sample(b);
      t = to > from ? float(v - from) / float(to - from) : 0.0f;
    };
    int y0, y1;
    float ty;
    bracket(y, sh - 1, sampleY, y0, y1, ty);
    for (int x = 0; x < w; ++x) {
      int x0, x1;
      float tx;
      bracket(x, sw - 1, sampleX, x0, x1, tx);
      const std::size_t a = std::size_t(y0) * sw + x0, b = std::size_t(y0) * sw + x1;
      const std::size_t c = std::size_t(y1) * sw + x0, d = std::size_t(y1) * sw + x1;
      auto mix = [&](const auto& v) {
        return (1 - ty) * ((1 - tx) * v[a] + tx * v[b]) + ty * ((1 - tx) * v[c] + tx * v[d]);
      };
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      year[i] = mix(sampledYear);
      yearAbove[i] = mix(sampledAbove);
      knot[i] = mix(sampledKnot);
      const glm::vec3 f = mix(sampledFibre);
      fibre[i] = step > 1 ? f / std::max(glm::length(f), 1e-9f) : f;
      out.inside[i] = block.contains(grid.point(float(x), float(y))) ? 1 : 0;
    }
  });
  const glm::vec3 rightUnit = glm::normalize(grid.right), downUnit = glm::normalize(grid.down);
  const float mmRight = glm::length(grid.right), mmDown = glm::length(grid.down);
  const WoodParameters& params = model.params();
  const float sapFrom = params.sapwoodStart - 0.5f * params.sapwoodTransition;
  const float sapTo = params.sapwoodStart + 0.5f * params.sapwoodTransition;
  std::vector<float> tensor(n * 5);  // grain tensor (xx, yy, xy) and in-plane gradient (x, y)
  std::vector<glm::vec2> ringInPlane(n);
  parallelRows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1);
      const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
      const float gx =
          x1 > x0 ? (year[std::size_t(y) * w + x1] - year[std::size_t(y) * w + x0]) / ((x1 - x0) * mmRight)
                  : 0.0f;
      const float gy =
          y1 > y0 ? (year[std::size_t(y1) * w + x] - year[std::size_t(y0) * w + x]) / ((y1 - y0) * mmDown)
                  : 0.0f;
      const float gn = (yearAbove[i] - year[i]) / stepMm;
      const float gradient = std::sqrt(gx * gx + gy * gy + gn * gn) + 1e-6f;
      // The grain direction: on side grain the fibre projected onto the surface (pores, fibre streaks and
      // rays run along it, and they are what a photo's local structure shows at a millimetre); on end grain,
      // where that projection vanishes, the ring tangent in the surface. Blended by the projection's
      // squared length (the squared sine of the angle between fibre and normal).
      const glm::vec3 f = fibre[i];
      const float fx = glm::dot(f, rightUnit), fy = glm::dot(f, downUnit);
      const float inPlane = std::sqrt(gx * gx + gy * gy);
      const float tx = -gy / (inPlane + 1e-9f), ty = gx / (inPlane + 1e-9f);
      const float fibreWeight = fx * fx + fy * fy;
      const float ringWeight = 1.0f - fibreWeight;
      const float fibreNorm = std::sqrt(fibreWeight) + 1e-9f;
      const float ux = fx / fibreNorm, uy = fy / fibreNorm;
      tensor[i * 5 + 0] = ringWeight * tx * tx + fibreWeight * ux * ux;
      tensor[i * 5 + 1] = ringWeight * ty * ty + fibreWeight * uy * uy;
      tensor[i * 5 + 2] = ringWeight * tx * ty + fibreWeight * ux * uy;
      tensor[i * 5 + 3] = gx;
      tensor[i * 5 + 4] = gy;
      // The ring tangent, as long as the sine of the angle between rings and surface, for the ring-angle
      // feature below.
      ringInPlane[i] = glm::vec2(tx, ty) * (inPlane / gradient);
      const float phase = model.material().yearPhase(year[i]);
      float* feature = &out.features[i * kGuidanceChannels];
      feature[0] = weights.phase * std::cos(kTwoPi * phase);
      feature[1] = weights.phase * std::sin(kTwoPi * phase);
      feature[2] = weights.sawing * std::abs(glm::dot(f, grid.normal));
      feature[3] = weights.sawing * std::abs(gn) / gradient;
      feature[4] = weights.density * std::log(std::max(gradient, 1e-3f));
      feature[5] = weights.sapwood * smoothStep(sapFrom, sapTo, year[i]);
      feature[6] = weights.year * year[i];
      feature[kKnotChannel] = weights.knot * knot[i];
    }
  });
  // The grain direction from the tensor averaged over about a millimetre (as a structure tensor is, and
  // as a patch sees it): the field's small wobbles turn single pixels' gradients a lot.
  const double sigma = kGrainScaleMm * grid.pxPerMm();
  const int shrink = sigma > kLargestDirectSigma ? static_cast<int>(sigma / (0.5 * kLargestDirectSigma)) : 1;
  for (int c = 0; c < 5; ++c) {
    cv::Mat channel(h, w, CV_32F);
    for (std::size_t i = 0; i < n; ++i) channel.at<float>(static_cast<int>(i)) = tensor[i * 5 + c];
    if (shrink > 1) {
      cv::Mat small;
      cv::resize(channel, small, cv::Size(std::max(1, w / shrink), std::max(1, h / shrink)), 0, 0,
                 cv::INTER_AREA);
      const double smallSigma = sigma * small.cols / w;
      cv::GaussianBlur(small, small, cv::Size(0, 0), smallSigma, smallSigma, cv::BORDER_REFLECT);
      cv::resize(small, channel, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
    } else {
      cv::GaussianBlur(channel, channel, cv::Size(0, 0), sigma, sigma, cv::BORDER_REFLECT);
    }
    for (std::size_t i = 0; i < n; ++i) tensor[i * 5 + c] = channel.at<float>(static_cast<int>(i));
  }
  parallelRows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const float* t = &tensor[i * 5];
      float angle = 0.5f * std::atan2(2.0f * t[2], t[0] - t[1]);
      if (-std::sin(angle) * t[3] + std::cos(angle) * t[4] < 0.0f) angle += std::numbers::pi_v<float>;
      out.grainAngle[i] = angle;
      // The ring bands' direction relative to the grain direction (doubled: a direction, not a vector), as
      // strong as the rings cross the surface: whether the bands run along the fibre (quarter-sawn stripes)
      // or across it (flat-sawn arches), so that a patch turned onto the grain also has its bands right.
      const glm::vec2 ring = ringInPlane[i];
      const float ringAngle = 2.0f * (std::atan2(ring.y, ring.x) - angle);
      const float ringLength = glm::length(ring);
      float* feature = &out.features[i * kGuidanceChannels];
      feature[7] = weights.ringAngle * ringLength * std::cos(ringAngle);
      feature[8] = weights.ringAngle * ringLength * std::sin(ringAngle);
    }
  });
  return out;
}

SurfaceGuidance halveGuidance(const SurfaceGuidance& g) {
  SurfaceGuidance out;
  out.width = std::max(1, g.width / 2);
  out.height = std::max(1, g.height / 2);
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  out.features.assign(n * kGuidanceChannels, 0.0f);
  out.grainAngle.assign(n, 0.0f);
  out.inside.assign(n, 0);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const std::size_t o = static_cast<std::size_t>(y) * out.width + x;
      float cx = 0, cy = 0;
      int count = 0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const int sx = std::min(2 * x + dx, g.width - 1), sy = std::min(2 * y + dy, g.height - 1);
          const std::size_t i = static_cast<std::size_t>(sy) * g.width + sx;
          for (int c = 0; c < kGuidanceChannels; ++c)
            out.features[o * kGuidanceChannels + c] += 0.25f * g.features[i * kGuidanceChannels + c];
          cx += std::cos(g.grainAngle[i]);
          cy += std::sin(g.grainAngle[i]);
          count += g.inside[i];
        }
      out.grainAngle[o] = std::atan2(cy, cx);
      out.inside[o] = count > 0 ? 1 : 0;
    }
  return out;
}

}  // namespace kerf
