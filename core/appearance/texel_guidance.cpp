#include "appearance/texel_guidance.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr float kGrainScaleMm = 0.8f;  // the grain tensor's averaging, as computeGuidance's
constexpr int kTensor = 5;             // grain tensor (xx, yy, xy), in-plane gradient (x, y)

// A texel's tangent frame: its steps right and down, and what maps a tangent vector to image coordinates
// (the pseudo-inverse of the 3 x 2 matrix [right down]: exact for vectors in the texel's plane).
struct TexelFrame {
  glm::vec3 right, down, normal;
  float rr, rd, dd, det;
  TexelFrame(glm::vec3 r, glm::vec3 d) : right(r), down(d) {
    normal = glm::normalize(glm::cross(r, d));
    rr = glm::dot(r, r), rd = glm::dot(r, d), dd = glm::dot(d, d);
    det = rr * dd - rd * rd;
  }
  bool valid() const { return det > 1e-12f * rr * dd && std::isfinite(det); }
  glm::vec2 toImage(glm::vec3 v) const {
    const float a = glm::dot(right, v), b = glm::dot(down, v);
    return glm::vec2(dd * a - rd * b, rr * b - rd * a) / det;
  }
};

float smoothStep(float a, float b, float x) {
  if (b <= a) return x < a ? 0.0f : 1.0f;
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 growthGradient(const WoodMaterial& material, glm::vec3 p, float stepMm) {
  glm::vec3 g;
  for (int a = 0; a < 3; ++a) {
    glm::vec3 e(0.0f);
    e[a] = stepMm;
    g[a] = (material.year(p + e) - material.year(p - e)) / (2.0f * stepMm);
  }
  return g;
}

// Averages the grain tensor with a Gaussian within each region (normalised convolution: what lies outside
// the region counts for nothing), so that charts side by side in the atlas do not turn each other's grain.
void averageWithinRegions(const TexelSurface& s, std::vector<float>& tensor) {
  struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    double mmSum = 0;
    int count = 0;
  };
  std::map<int, Box> boxes;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * s.width + x;
      if (s.region[i] < 0) continue;
      Box& b = boxes[s.region[i]];
      b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
      b.mmSum += std::sqrt(glm::length(s.right[i]) * glm::length(s.down[i]));
      ++b.count;
    }
  for (const auto& [region, b] : boxes) {
    const double sigma = kGrainScaleMm / (b.mmSum / b.count);
    const int w = b.x1 - b.x0 + 1, h = b.y1 - b.y0 + 1;
    cv::Mat mask(h, w, CV_32F), weight;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        mask.at<float>(y, x) = s.region[std::size_t(b.y0 + y) * s.width + b.x0 + x] == region ? 1.0f : 0.0f;
    cv::GaussianBlur(mask, weight, cv::Size(0, 0), sigma, sigma, cv::BORDER_CONSTANT);
    for (int c = 0; c < kTensor; ++c) {
      cv::Mat channel(h, w, CV_32F);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          channel.at<float>(y, x) =
              mask.at<float>(y, x) * tensor[(std::size_t(b.y0 + y) * s.width + b.x0 + x) * kTensor + c];
      cv::GaussianBlur(channel, channel, cv::Size(0, 0), sigma, sigma, cv::BORDER_CONSTANT);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (mask.at<float>(y, x) > 0.0f)
            tensor[(std::size_t(b.y0 + y) * s.width + b.x0 + x) * kTensor + c] =
                channel.at<float>(y, x) / std::max(weight.at<float>(y, x), 1e-6f);
    }
  }
}

// Every texel of no region takes the features of the nearest texel of one (breadth first, 4-neighbours).
void fillGutter(const TexelSurface& s, SurfaceGuidance& g) {
  std::vector<int> from(g.inside.size(), -1);
  std::deque<int> queue;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (g.inside[i]) from[i] = int(i), queue.push_back(int(i));
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const int x = i % s.width, y = i / s.width;
    const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& [nx, ny] : next) {
      if (nx < 0 || ny < 0 || nx >= s.width || ny >= s.height) continue;
      const int j = ny * s.width + nx;
      if (from[j] >= 0) continue;
      from[j] = from[i];
      queue.push_back(j);
    }
  }
  for (std::size_t i = 0; i < from.size(); ++i) {
    if (g.inside[i] || from[i] < 0) continue;
    std::copy_n(&g.features[std::size_t(from[i]) * kGuidanceChannels], kGuidanceChannels,
                &g.features[i * kGuidanceChannels]);
    g.grainAngle[i] = g.grainAngle[from[i]];
  }
}

}  // namespace

SurfaceGuidance computeTexelGuidance(const WoodModel& model, const TexelSurface& s,
                                     const GuidanceWeights& weights, const Progress& progress) {
  const std::size_t n = static_cast<std::size_t>(s.width) * s.height;
  if (s.point.size() != n || s.right.size() != n || s.down.size() != n || s.region.size() != n)
    throw InputError("texel guidance: the texels' points, frames and regions differ in number");
  SurfaceGuidance out;
  out.width = s.width;
  out.height = s.height;
  out.features.assign(n * kGuidanceChannels, 0.0f);
  out.grainAngle.assign(n, 0.0f);
  out.inside.assign(n, 0);
  const WoodParameters& params = model.params();
  const float sapFrom = params.sapwoodStart - 0.5f * params.sapwoodTransition;
  const float sapTo = params.sapwoodStart + 0.5f * params.sapwoodTransition;
  std::vector<float> tensor(n * kTensor, 0.0f);
  std::vector<glm::vec2> ringInPlane(n);
  parallelRows(
      s.height,
      [&](int y) {
        for (int x = 0; x < s.width; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * s.width + x;
          if (s.region[i] < 0) continue;
          const TexelFrame frame(s.right[i], s.down[i]);
          if (!frame.valid()) continue;
          out.inside[i] = 1;
          // Where the texel lies in the tree (year, fibre, knot), without shading it.
          const auto sample = model.material().locate(s.point[i], true);
          const float stepMm = 0.5f * std::min(glm::length(s.right[i]), glm::length(s.down[i]));
          const glm::vec3 grad = growthGradient(model.material(), s.point[i], stepMm);
          const float gradient = glm::length(grad) + 1e-6f;
          const float gn = glm::dot(grad, frame.normal);
          const float inPlane = std::sqrt(std::max(0.0f, glm::dot(grad, grad) - gn * gn));
          // The growth gradient as a covector in the image, per mm along each image axis; the rings run
          // along its kernel (exact in a non-orthogonal frame, where the gradient's image is not normal to
          // the rings).
          const glm::vec2 g(glm::dot(grad, s.right[i]) / glm::length(s.right[i]),
                            glm::dot(grad, s.down[i]) / glm::length(s.down[i]));
          const glm::vec2 ringTangent =
              glm::vec2(-glm::dot(grad, s.down[i]), glm::dot(grad, s.right[i])) /
              (std::hypot(glm::dot(grad, s.down[i]), glm::dot(grad, s.right[i])) + 1e-12f);
          // The fibre's projection onto the surface, carried into the image through the texel's frame.
          const glm::vec3 f = sample.fiberDirection;
          const glm::vec3 fibreInPlane = f - glm::dot(f, frame.normal) * frame.normal;
          const float fibreWeight = std::min(1.0f, glm::dot(fibreInPlane, fibreInPlane));
          const glm::vec2 fibreImage = frame.toImage(fibreInPlane);
          const glm::vec2 u = fibreImage / (glm::length(fibreImage) + 1e-12f);
          const glm::vec2 t = ringTangent;
          const float ringWeight = 1.0f - fibreWeight;
          float* tn = &tensor[i * kTensor];
          tn[0] = ringWeight * t.x * t.x + fibreWeight * u.x * u.x;
          tn[1] = ringWeight * t.y * t.y + fibreWeight * u.y * u.y;
          tn[2] = ringWeight * t.x * t.y + fibreWeight * u.x * u.y;
          tn[3] = g.x;
          tn[4] = g.y;
          ringInPlane[i] = t * (inPlane / gradient);
          float* feature = &out.features[i * kGuidanceChannels];
          const float phase = model.material().yearPhase(sample.year);
          feature[0] = weights.phase * std::cos(kTwoPi * phase);
          feature[1] = weights.phase * std::sin(kTwoPi * phase);
          feature[2] = weights.sawing * std::abs(glm::dot(f, frame.normal));
          feature[3] = weights.sawing * std::abs(gn) / gradient;
          feature[4] = weights.density * std::log(std::max(gradient, 1e-3f));
          feature[5] = weights.sapwood * smoothStep(sapFrom, sapTo, sample.year);
          feature[6] = weights.year * sample.year;
          feature[kKnotChannel] = weights.knot * sample.knotDarkness;
        }
      },
      progress.part(0.0, 0.9));
  progress.throwIfCancelled();
  averageWithinRegions(s, tensor);
  // The grain angle from the averaged tensor, signed so that the growth increases to its left, and the
  // ring bands' direction relative to it: as computeGuidance.
  parallelRows(s.height, [&](int y) {
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * s.width + x;
      if (!out.inside[i]) continue;
      const float* tn = &tensor[i * kTensor];
      float angle = 0.5f * std::atan2(2.0f * tn[2], tn[0] - tn[1]);
      if (-std::sin(angle) * tn[3] + std::cos(angle) * tn[4] < 0.0f) angle += std::numbers::pi_v<float>;
      out.grainAngle[i] = angle;
      const float bands = 2.0f * (std::atan2(ringInPlane[i].y, ringInPlane[i].x) - angle);
      const float strength = weights.ringAngle * glm::length(ringInPlane[i]);
      out.features[i * kGuidanceChannels + 7] = strength * std::cos(bands);
      out.features[i * kGuidanceChannels + 8] = strength * std::sin(bands);
    }
  });
  fillGutter(s, out);
  progress.set(1.0);
  return out;
}

}  // namespace kerf
