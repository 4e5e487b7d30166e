#include "rings/learned_ring_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "rings/ring_metrics.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

// The network halves the resolution three times: its input sides must be multiples of 8.
constexpr int kSideMultiple = 8;

cv::Mat toRgbMat(const Image& photo) {
  cv::Mat out(photo.height, photo.width, CV_32FC3);
  for (int y = 0; y < photo.height; ++y) {
    auto* row = out.ptr<cv::Vec3f>(y);
    for (int x = 0; x < photo.width; ++x) {
      const float* p = photo.pixel(x, y);
      row[x] = photo.channels >= 3 ? cv::Vec3f(p[0], p[1], p[2]) : cv::Vec3f(p[0], p[0], p[0]);
    }
  }
  return out;
}

// What scripts/train_ring_detector.py's normalise() does: each channel minus its mean, all divided by
// the image's standard deviation (white balance and exposure drop out).
cv::Mat normalised(const cv::Mat& rgb) {
  const cv::Scalar mean = cv::mean(rgb);
  cv::Mat centred = rgb - mean;
  const double variance = cv::mean(centred.mul(centred)).dot(cv::Scalar(1, 1, 1, 0)) / 3.0;
  return centred / (std::sqrt(variance) + 1e-3);
}

cv::dnn::Net loadNet(std::span<const std::byte> onnx, const std::string& what) {
  try {
    cv::dnn::Net net = cv::dnn::readNetFromONNX(reinterpret_cast<const char*>(onnx.data()), onnx.size());
    if (net.empty()) throw InputError(what + ": not a ring detector network");
    return net;
  } catch (const cv::Exception& e) {
    throw InputError(what + ": the network does not load (" + e.msg + ")");
  }
}

// The network's ring probability -> crisp boundaries, as the classical detector's last steps make them:
// ridge lines of the probability (rings/ring_metrics.hpp), kept where a connected line reaches `high`
// somewhere (hysteresis from `low`) and is at least `minLengthPx` long. The network is least sure on
// real photos (it saw only rendered wood), so its bands there are broad and grey; their ridges are where it
// is surest.
cv::Mat ringBoundaries(const cv::Mat& probability, const LearnedRingParams& P, float pxPerMm) {
  cv::Mat smooth = probability;
  if (P.smoothMm * pxPerMm > 0.3f)
    cv::GaussianBlur(probability, smooth, cv::Size(0, 0), P.smoothMm * pxPerMm, 0, cv::BORDER_REFLECT);
  Image asImage(probability.cols, probability.rows, 1);
  for (int y = 0; y < probability.rows; ++y)
    for (int x = 0; x < probability.cols; ++x) asImage.pixel(x, y)[0] = smooth.at<float>(y, x);
  const Image ridges = ringRidgePixels(asImage, P.lowThreshold);
  cv::Mat ridge(probability.rows, probability.cols, CV_8U);
  for (int y = 0; y < ridge.rows; ++y)
    for (int x = 0; x < ridge.cols; ++x) ridge.at<unsigned char>(y, x) = ridges.pixel(x, y)[0] > 0.5f ? 1 : 0;
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(ridge, labels, stats, centroids, 8, CV_32S);
  std::vector<float> peak(static_cast<std::size_t>(count), 0.0f);
  for (int y = 0; y < ridge.rows; ++y)
    for (int x = 0; x < ridge.cols; ++x) {
      const int l = labels.at<int>(y, x);
      if (l > 0) peak[l] = std::max(peak[l], probability.at<float>(y, x));
    }
  const int minLength = std::max(3, static_cast<int>(std::lround(P.minLengthMm * pxPerMm)));
  cv::Mat boundary(ridge.rows, ridge.cols, CV_8U, cv::Scalar(0));
  for (int y = 0; y < ridge.rows; ++y)
    for (int x = 0; x < ridge.cols; ++x) {
      const int l = labels.at<int>(y, x);
      if (l > 0 && peak[l] >= P.highThreshold && stats.at<int>(l, cv::CC_STAT_AREA) >= minLength)
        boundary.at<unsigned char>(y, x) = 1;
    }
  return boundary;
}

// Mokume Eq. 1's profile of the distance to the nearest boundary over the ring width, the width measured
// as twice the median distance on the medial ridges between boundaries (the classical detector's step 6).
Image ringLocalizationFromBoundaries(const cv::Mat& boundary, const LearnedRingParams& P, float pxPerMm) {
  Image arl(boundary.cols, boundary.rows, 1);
  if (cv::countNonZero(boundary) == 0) return arl;
  cv::Mat distance;
  cv::distanceTransform(boundary == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const float minWidth = std::max(2.0f, P.minRingWidthMm * pxPerMm), maxWidth = P.maxRingWidthMm * pxPerMm;
  std::vector<float> medial;
  for (int y = 1; y + 1 < distance.rows; ++y)
    for (int x = 1; x + 1 < distance.cols; ++x) {
      const float d = distance.at<float>(y, x);
      if (d < 1.0f || 2 * d > maxWidth) continue;
      // A medial pixel: no farther pixel on at least one of the four lines through it.
      bool ridge = false;
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}, std::pair{1, -1}})
        ridge = ridge || (d >= distance.at<float>(y + dy, x + dx) && d >= distance.at<float>(y - dy, x - dx));
      if (ridge) medial.push_back(d);
    }
  float width = 3.0f * pxPerMm;
  if (!medial.empty()) {
    std::nth_element(medial.begin(), medial.begin() + medial.size() / 2, medial.end());
    width = 2.0f * medial[medial.size() / 2];
  }
  width = std::clamp(width, minWidth, std::max(minWidth, maxWidth));
  for (int y = 0; y < arl.height; ++y)
    for (int x = 0; x < arl.width; ++x) {
      const float g = std::min(distance.at<float>(y, x) / width, 0.5f);
      arl.pixel(x, y)[0] = std::pow(0.5f * (std::cos(2.0f * std::numbers::pi_v<float> * g) + 1.0f), P.power);
    }
  return arl;
}

}  // namespace

LearnedRingDetector::LearnedRingDetector(LearnedRingParams params)
    : LearnedRingDetector(builtInRingDetectorModel(), "the built-in ring detector", params) {}

LearnedRingDetector::LearnedRingDetector(std::span<const std::byte> onnx, std::string what,
                                         LearnedRingParams params)
    : model_(onnx), what_(std::move(what)), params_(params) {
  loadNet(model_, what_);  // fail here, not at the first photo
}

Image LearnedRingDetector::localize(const Image& photo, float pxPerMm, const Progress& progress) const {
  if (photo.empty() || photo.width < 1 || photo.height < 1) throw InputError("ring detection: empty photo");
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("ring detection: the photo's pixels per millimetre must be positive");
  progress.throwIfCancelled();
  // Resample to the network's resolution, then pad (mirrored) to a multiple of 8 px.
  const double scale = kLearnedDetectorPxPerMm / pxPerMm;
  const cv::Size work(std::max(1, static_cast<int>(std::lround(photo.width * scale))),
                      std::max(1, static_cast<int>(std::lround(photo.height * scale))));
  cv::Mat rgb = toRgbMat(photo), resampled;
  cv::resize(rgb, resampled, work, 0, 0, scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  const int padX = (kSideMultiple - work.width % kSideMultiple) % kSideMultiple + kSideMultiple;
  const int padY = (kSideMultiple - work.height % kSideMultiple) % kSideMultiple + kSideMultiple;
  cv::Mat padded;
  cv::copyMakeBorder(normalised(resampled), padded, padY / 2, padY - padY / 2, padX / 2, padX - padX / 2,
                     cv::BORDER_REFLECT_101);
  progress.set(0.1);
  cv::dnn::Net net = loadNet(model_, what_);     // one per call: a Net is not safe to share between threads
  net.setInput(cv::dnn::blobFromImage(padded));  // HWC float -> 1 x 3 x H x W, no scaling or swap
  progress.throwIfCancelled();
  const cv::Mat out = net.forward();
  progress.throwIfCancelled();
  if (out.dims != 4 || out.size[2] != padded.rows || out.size[3] != padded.cols)
    throw InputError(what_ + ": the network's output has another size than its input");
  const cv::Mat ring(padded.rows, padded.cols, CV_32F, const_cast<float*>(out.ptr<float>()));
  cv::Mat cropped = ring(cv::Rect(padX / 2, padY / 2, work.width, work.height)), full;
  cv::resize(cropped, full, cv::Size(photo.width, photo.height), 0, 0, cv::INTER_LINEAR);
  full = cv::max(cv::min(full, 1.0), 0.0);
  if (!params_.crisp) {
    Image probability(photo.width, photo.height, 1);
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) probability.pixel(x, y)[0] = full.at<float>(y, x);
    progress.set(1.0);
    return probability;
  }
  Image arl = ringLocalizationFromBoundaries(ringBoundaries(full, params_, pxPerMm), params_, pxPerMm);
  progress.set(1.0);
  return arl;
}

const RingDetector& ringDetectorNamed(const std::string& name) {
  static const ClassicalRingDetector classical;
  if (name == "classical") return classical;
  if (name == "learned") {
    static const LearnedRingDetector learned;
    return learned;
  }
  throw InputError("unknown ring detector '" + name + "' (use classical or learned)");
}

}  // namespace kerf
