#include "rings/ring_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "render/wood_model.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

cv::Mat channel0(const Image& image) {
  cv::Mat m(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) m.at<float>(y, x) = image.pixel(x, y)[0];
  return m;
}

float at(const cv::Mat& m, float x, float y) {
  x = std::clamp(x, 0.0f, static_cast<float>(m.cols - 1));
  y = std::clamp(y, 0.0f, static_cast<float>(m.rows - 1));
  const int x0 = std::min(static_cast<int>(x), std::max(0, m.cols - 2));
  const int y0 = std::min(static_cast<int>(y), std::max(0, m.rows - 2));
  const int x1 = std::min(x0 + 1, m.cols - 1), y1 = std::min(y0 + 1, m.rows - 1);
  const float fx = x - x0, fy = y - y0;
  return (m.at<float>(y0, x0) * (1 - fx) + m.at<float>(y0, x1) * fx) * (1 - fy) +
         (m.at<float>(y1, x0) * (1 - fx) + m.at<float>(y1, x1) * fx) * fy;
}

cv::Mat distanceToMask(const Image& mask) {
  cv::Mat zeroOnMask(mask.height, mask.width, CV_8U);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      zeroOnMask.at<unsigned char>(y, x) = mask.pixel(x, y)[0] > 0.5f ? 0 : 255;
  cv::Mat distance;
  cv::distanceTransform(zeroOnMask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

}  // namespace

Image ringRidgePixels(const Image& arl, float threshold) {
  Image out(arl.width, arl.height, 1);
  if (arl.empty()) return out;
  const cv::Mat value = channel0(arl);
  cv::Mat smooth;
  cv::GaussianBlur(value, smooth, cv::Size(0, 0), 1.0, 1.0, cv::BORDER_REFLECT);
  cv::Mat dxx, dyy, dxy;
  cv::Sobel(smooth, dxx, CV_32F, 2, 0, 3, 1, 0, cv::BORDER_REFLECT);
  cv::Sobel(smooth, dyy, CV_32F, 0, 2, 3, 1, 0, cv::BORDER_REFLECT);
  cv::Sobel(smooth, dxy, CV_32F, 1, 1, 3, 1, 0, cv::BORDER_REFLECT);
  for (int y = 0; y < arl.height; ++y)
    for (int x = 0; x < arl.width; ++x) {
      if (value.at<float>(y, x) < threshold) continue;
      const float a = dxx.at<float>(y, x), b = dyy.at<float>(y, x), c = dxy.at<float>(y, x);
      // Eigenvector of the smaller (most negative) eigenvalue of [[a c][c b]].
      const float root = std::sqrt((a - b) * (a - b) + 4 * c * c);
      const float lambda = 0.5f * (a + b - root);
      float ex = c, ey = lambda - a;
      if (std::abs(ex) + std::abs(ey) < 1e-12f) {
        ex = lambda - b;
        ey = c;
      }
      const float len = std::sqrt(ex * ex + ey * ey);
      if (len < 1e-12f) {
        ex = 1;
        ey = 0;
      } else {
        ex /= len;
        ey /= len;
      }
      const float v = smooth.at<float>(y, x);
      if (v >= at(smooth, x + ex, y + ey) && v >= at(smooth, x - ex, y - ey)) out.pixel(x, y)[0] = 1.0f;
    }
  return out;
}

namespace {

// Marks where `phase` crosses a whole number between 4-neighbours (the nearer of the two pixels).
Image markCrossings(const std::vector<float>& phase, glm::ivec2 size) {
  Image out(size.x, size.y, 1);
  const auto mark = [&](int x0, int y0, int x1, int y1) {
    const float a = phase[static_cast<std::size_t>(y0) * size.x + x0];
    const float b = phase[static_cast<std::size_t>(y1) * size.x + x1];
    if (std::floor(a) == std::floor(b)) return;
    const float level = std::floor(std::max(a, b));  // the whole number crossed (nearest one to the larger)
    if (std::abs(a - level) <= std::abs(b - level))
      out.pixel(x0, y0)[0] = 1.0f;
    else
      out.pixel(x1, y1)[0] = 1.0f;
  };
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      if (x + 1 < size.x) mark(x, y, x + 1, y);
      if (y + 1 < size.y) mark(x, y, x, y + 1);
    }
  return out;
}

}  // namespace

Image trueRingPixels(const WoodModel& model, FaceId face, glm::ivec2 size) {
  const float offset = model.params().ringOffset;
  std::vector<float> phase(static_cast<std::size_t>(size.x) * size.y);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      phase[static_cast<std::size_t>(y) * size.x + x] =
          model.material().year(model.block().pixelCenter(face, x, y, size)) - offset;
  return markCrossings(phase, size);
}

Image ringLinePixels(const std::function<double(glm::vec3)>& years, double offset, glm::vec3 origin,
                     glm::vec3 du, glm::vec3 dv, glm::ivec2 size) {
  std::vector<float> phase(static_cast<std::size_t>(size.x) * size.y);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      phase[static_cast<std::size_t>(y) * size.x + x] =
          static_cast<float>(years(origin + (x + 0.5f) * du + (y + 0.5f) * dv) - offset);
  return markCrossings(phase, size);
}

RingAgreement compareRingPixels(const Image& detected, const Image& reference, float tolerancePx) {
  if (detected.width != reference.width || detected.height != reference.height)
    throw InputError("ring comparison: the two masks differ in size");
  const cv::Mat toReference = distanceToMask(reference), toDetected = distanceToMask(detected);
  RingAgreement r;
  long detectedNear = 0, referenceNear = 0;
  for (int y = 0; y < detected.height; ++y)
    for (int x = 0; x < detected.width; ++x) {
      if (detected.pixel(x, y)[0] > 0.5f) {
        ++r.detectedPixels;
        if (toReference.at<float>(y, x) <= tolerancePx) ++detectedNear;
      }
      if (reference.pixel(x, y)[0] > 0.5f) {
        ++r.referencePixels;
        if (toDetected.at<float>(y, x) <= tolerancePx) ++referenceNear;
      }
    }
  r.precision = r.detectedPixels ? static_cast<double>(detectedNear) / r.detectedPixels : 0.0;
  r.recall = r.referencePixels ? static_cast<double>(referenceNear) / r.referencePixels : 0.0;
  return r;
}

}  // namespace kerf
