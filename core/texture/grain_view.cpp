#include "texture/grain_view.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace kerf {
namespace {

// Luminance after the image's own white balance (each channel over twice its mean).
cv::Mat balancedLuminance(const Image& image) {
  if (image.channels < 3) throw InputError("grain view: a colour image is needed");
  double mean[3] = {0, 0, 0};
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) mean[c] += image.pixels[i * image.channels + c];
  float scale[3];
  for (int c = 0; c < 3; ++c)
    scale[c] = static_cast<float>(1.0 / (2.0 * mean[c] / std::max<std::size_t>(n, 1) + 1e-6));
  cv::Mat lum(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      lum.at<float>(y, x) = 0.299f * p[0] * scale[0] + 0.587f * p[1] * scale[1] + 0.114f * p[2] * scale[2];
    }
  return lum;
}

cv::Mat blurred(const cv::Mat& m, double sigma) {
  cv::Mat out;
  cv::GaussianBlur(m, out, cv::Size(), sigma, sigma, cv::BORDER_REFLECT101);
  return out;
}

// Correlation of `detail` with itself shifted by (dx, dy) px, over the pixels where both lie inside the
// image and `margin` px from its border.
double shiftedCorrelation(const cv::Mat& detail, double dx, double dy, int margin) {
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, -dx, 0, 1, -dy);
  cv::Mat moved;
  cv::warpAffine(detail, moved, shift, detail.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT101);
  const int mx = margin + static_cast<int>(std::ceil(std::abs(dx))),
            my = margin + static_cast<int>(std::ceil(std::abs(dy)));
  if (detail.cols - 2 * mx < 4 || detail.rows - 2 * my < 4) return 0.0;
  const cv::Rect inside(mx, my, detail.cols - 2 * mx, detail.rows - 2 * my);
  cv::Scalar meanA, spreadA, meanB, spreadB;
  const cv::Mat a = detail(inside), b = moved(inside);
  cv::meanStdDev(a, meanA, spreadA);
  cv::meanStdDev(b, meanB, spreadB);
  if (spreadA[0] < 1e-9 || spreadB[0] < 1e-9) return 0.0;
  const double covariance = cv::mean((a - meanA[0]).mul(b - meanB[0]))[0];
  return covariance / (spreadA[0] * spreadB[0]);
}

}  // namespace

GrainView grainViewOf(const Image& image, double pxPerMm) {
  if (!(pxPerMm > 0)) throw InputError("grain view: the scale must be positive");
  const double k = pxPerMm / kYardstickPxPerMm;
  const cv::Mat lum = balancedLuminance(image);
  GrainView view;
  view.width = image.width, view.height = image.height;
  view.margin = static_cast<int>(std::lround(12.0 * k));
  cv::Scalar mean, spread;
  cv::meanStdDev(blurred(lum, 1.5 * k) - blurred(lum, 8.0 * k), mean, spread);
  view.bandSpread = spread[0];
  const cv::Mat figure = blurred(lum, 3.0 * k) - blurred(lum, 16.0 * k);
  view.figure.assign(figure.begin<float>(), figure.end<float>());

  cv::Mat gx, gy;
  const cv::Mat smooth = blurred(lum, 1.0 * k);
  cv::Sobel(smooth, gx, CV_32F, 1, 0);
  cv::Sobel(smooth, gy, CV_32F, 0, 1);
  const double window = 6.0 * k;
  const cv::Mat j11 = blurred(gx.mul(gx), window), j22 = blurred(gy.mul(gy), window),
                j12 = blurred(gx.mul(gy), window);
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  // The lines run across the mean dominant gradient; the fine detail's self-correlation along them.
  const double lines = 0.5 * std::atan2(2.0 * cv::mean(j12)[0], cv::mean(j11)[0] - cv::mean(j22)[0]) +
                       0.5 * 3.14159265358979323846;
  const cv::Mat detail = smooth - blurred(lum, 8.0 * k);
  const double lagsMm[3] = {1.0, 2.0, 4.0};
  for (int i = 0; i < 3; ++i) {
    const double lag = lagsMm[i] * pxPerMm;
    view.streak[i] = shiftedCorrelation(detail, lag * std::cos(lines), lag * std::sin(lines), view.margin);
  }
  view.direction.resize(n), view.coherence.resize(n);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float a = j11.at<float>(y, x), b = j22.at<float>(y, x), c = j12.at<float>(y, x);
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      view.direction[i] = 0.5f * std::atan2(2.0f * c, a - b);
      view.coherence[i] = std::sqrt((a - b) * (a - b) + 4.0f * c * c) / (a + b + 1e-9f);
    }
  return view;
}

double grainAgreement(const GrainView& render, const GrainView& photo) {
  const int margin = photo.margin;
  if (render.width != photo.width || render.height != photo.height)
    throw InputError("grain agreement: the render and the photo differ in size");
  double agree = 0, photoNorm = 0, renderNorm = 0;
  for (int y = margin; y < photo.height - margin; ++y)
    for (int x = margin; x < photo.width - margin; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * photo.width + x;
      const double cp = photo.coherence[i], cr = render.coherence[i];
      agree += cp * cr * std::cos(2.0 * (photo.direction[i] - render.direction[i]));
      photoNorm += cp * cp, renderNorm += cr * cr;
    }
  const double norm = std::sqrt(photoNorm * renderNorm);
  return norm > 1e-12 ? agree / norm : 0.0;
}

double figureCorrelation(const GrainView& render, const GrainView& photo) {
  const int margin = photo.margin;
  if (render.width != photo.width || render.height != photo.height)
    throw InputError("figure correlation: the render and the photo differ in size");
  double sr = 0, sp = 0, srr = 0, spp = 0, srp = 0, n = 0;
  for (int y = margin; y < photo.height - margin; ++y)
    for (int x = margin; x < photo.width - margin; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * photo.width + x;
      const double r = render.figure[i], p = photo.figure[i];
      sr += r, sp += p, srr += r * r, spp += p * p, srp += r * p, n += 1;
    }
  if (n < 2) return 0.0;
  const double covariance = srp - sr * sp / n;
  const double varianceR = srr - sr * sr / n, varianceP = spp - sp * sp / n;
  return varianceR > 1e-12 && varianceP > 1e-12 ? covariance / std::sqrt(varianceR * varianceP) : 0.0;
}

double contrastRatio(const GrainView& render, const GrainView& photo) {
  return render.bandSpread / (photo.bandSpread + 1e-9);
}

double streakDifference(const GrainView& render, const GrainView& photo) {
  double sum = 0;
  for (std::size_t i = 0; i < render.streak.size(); ++i) sum += std::abs(render.streak[i] - photo.streak[i]);
  return sum / render.streak.size();
}

}  // namespace kerf
