#pragma once
// The measures the photo-true tests compare a synthesis with the truth by: band-pass correlation and
// grain-orientation agreement, as ../shared/eval/appearance_eval.py defines them, on small images.
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "io/image.hpp"

namespace kerf::testing {

inline cv::Mat luminance(const Image& image) {
  cv::Mat out(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      out.at<float>(y, x) = 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
    }
  return out;
}

inline cv::Mat bandPass(const cv::Mat& g) {
  cv::Mat a, b;
  cv::GaussianBlur(g, a, cv::Size(0, 0), 0.75);
  cv::GaussianBlur(g, b, cv::Size(0, 0), 4.0);
  return a - b;
}

inline constexpr int kBorder = 6;  // filters' borders left out

inline double bandPassCorrelation(const Image& render, const Image& truth) {
  const cv::Mat a = bandPass(luminance(render)), b = bandPass(luminance(truth));
  const cv::Rect inner(kBorder, kBorder, a.cols - 2 * kBorder, a.rows - 2 * kBorder);
  cv::Mat x = a(inner) - cv::mean(a(inner))[0], y = b(inner) - cv::mean(b(inner))[0];
  return x.dot(y) / std::sqrt(x.dot(x) * y.dot(y) + 1e-12);
}

// Structure-tensor orientation agreement weighted by both coherences (the evaluator's "orient").
inline double orientationAgreement(const Image& render, const Image& truth) {
  auto tensor = [](const cv::Mat& lum, cv::Mat& theta, cv::Mat& coherence) {
    cv::Mat g, gx, gy;
    cv::GaussianBlur(lum, g, cv::Size(0, 0), 0.5);
    cv::Sobel(g, gx, CV_32F, 1, 0);
    cv::Sobel(g, gy, CV_32F, 0, 1);
    cv::Mat j11 = gx.mul(gx), j22 = gy.mul(gy), j12 = gx.mul(gy);
    for (cv::Mat* m : {&j11, &j22, &j12}) cv::GaussianBlur(*m, *m, cv::Size(0, 0), 3.0);
    theta.create(lum.size(), CV_32F);
    coherence.create(lum.size(), CV_32F);
    for (int y = 0; y < lum.rows; ++y)
      for (int x = 0; x < lum.cols; ++x) {
        const float a = j11.at<float>(y, x), b = j22.at<float>(y, x), c = j12.at<float>(y, x);
        theta.at<float>(y, x) = 0.5f * std::atan2(2 * c, a - b);
        coherence.at<float>(y, x) = std::sqrt((a - b) * (a - b) + 4 * c * c) / (a + b + 1e-9f);
      }
  };
  cv::Mat tr, cr, tp, cp;
  tensor(luminance(render), tr, cr);
  tensor(luminance(truth), tp, cp);
  double num = 0, den = 0;
  for (int y = kBorder; y < tr.rows - kBorder; ++y)
    for (int x = kBorder; x < tr.cols - kBorder; ++x) {
      num +=
          cp.at<float>(y, x) * cr.at<float>(y, x) * std::cos(2 * (tp.at<float>(y, x) - tr.at<float>(y, x)));
      den += cp.at<float>(y, x) * cp.at<float>(y, x);
    }
  return num / (den + 1e-12);
}

inline Image rotatedQuarter(const Image& image) {  // an unrelated image with the same colours and detail
  Image out(image.height, image.width, image.channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      std::copy_n(image.pixel(x, y), image.channels, out.pixel(image.height - 1 - y, x));
  return out;
}

}  // namespace kerf::testing
