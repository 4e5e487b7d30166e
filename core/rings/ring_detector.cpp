#include "rings/ring_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <queue>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

cv::Mat luminance(const Image& photo) {
  cv::Mat out(photo.height, photo.width, CV_32F);
  for (int y = 0; y < photo.height; ++y) {
    auto* row = out.ptr<float>(y);
    for (int x = 0; x < photo.width; ++x) {
      const float* p = photo.pixel(x, y);
      row[x] = photo.channels >= 3 ? 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2] : p[0];
    }
  }
  return out;
}

cv::Mat gaussian(const cv::Mat& m, float sigmaPx) {
  if (sigmaPx < 0.2f) return m.clone();
  cv::Mat out;
  cv::GaussianBlur(m, out, cv::Size(0, 0), sigmaPx, sigmaPx, cv::BORDER_REFLECT);
  return out;
}

// Bilinear sample with the coordinates clamped to the image (pixel centres at integer positions here).
float sample(const cv::Mat& m, float x, float y) {
  x = std::clamp(x, 0.0f, static_cast<float>(m.cols - 1));
  y = std::clamp(y, 0.0f, static_cast<float>(m.rows - 1));
  const int x0 = std::min(static_cast<int>(x), m.cols - 2 < 0 ? 0 : m.cols - 2);
  const int y0 = std::min(static_cast<int>(y), m.rows - 2 < 0 ? 0 : m.rows - 2);
  const int x1 = std::min(x0 + 1, m.cols - 1), y1 = std::min(y0 + 1, m.rows - 1);
  const float fx = x - x0, fy = y - y0;
  const float a = m.at<float>(y0, x0), b = m.at<float>(y0, x1);
  const float c = m.at<float>(y1, x0), d = m.at<float>(y1, x1);
  return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

Image toImage(const cv::Mat& m) {
  Image out(m.cols, m.rows, 1);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) out.pixel(x, y)[0] = m.at<float>(y, x);
  return out;
}

// Gives the normals (nx, ny) a consistent sign over the image: quality-guided propagation from the
// most coherent pixel, each pixel taking the sign that agrees with the neighbour it is reached from.
void orientNormals(cv::Mat& nx, cv::Mat& ny, const cv::Mat& coherence) {
  const int w = nx.cols, h = nx.rows;
  std::vector<unsigned char> done(static_cast<std::size_t>(w) * h, 0);
  using Item = std::pair<float, int>;
  std::priority_queue<Item> queue;
  cv::Point best;
  cv::minMaxLoc(coherence, nullptr, nullptr, nullptr, &best);
  const int seed = best.y * w + best.x;
  done[seed] = 1;
  queue.push({coherence.at<float>(best), seed});
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  while (!queue.empty()) {
    const int i = queue.top().second;
    queue.pop();
    const int x = i % w, y = i / w;
    const float px = nx.at<float>(y, x), py = ny.at<float>(y, x);
    for (int k = 0; k < 4; ++k) {
      const int qx = x + dx[k], qy = y + dy[k];
      if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
      const int j = qy * w + qx;
      if (done[j]) continue;
      done[j] = 1;
      float& qnx = nx.at<float>(qy, qx);
      float& qny = ny.at<float>(qy, qx);
      if (qnx * px + qny * py < 0) {
        qnx = -qnx;
        qny = -qny;
      }
      queue.push({coherence.at<float>(qy, qx), j});
    }
  }
}

}  // namespace

Image ClassicalRingDetector::localize(const Image& photo, float pxPerMm, const Progress& progress) const {
  return detect(photo, pxPerMm, progress).arl;
}

ClassicalRingResult ClassicalRingDetector::detect(const Image& photo, float pxPerMm,
                                                  const Progress& progress) const {
  if (photo.empty() || photo.width < 4 || photo.height < 4)
    throw InputError("ring detection: the photo is empty or smaller than 4x4 pixels");
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("ring detection: pixels per millimetre must be positive");
  const ClassicalRingParams& P = params_;
  const Progress rowsOnly{{}, progress.stop};  // cancellable row loops, progress reported here
  const int w = photo.width, h = photo.height;
  const auto px = [&](float mm) { return mm * pxPerMm; };

  // 1. Luminance, pore closing, illumination flattening and contrast normalisation.
  const auto flatten = [&](const cv::Mat& lum) {
    const cv::Mat mean = gaussian(lum, px(P.illuminationSigmaMm));
    const cv::Mat centred = lum - mean;
    const cv::Mat var = gaussian(centred.mul(centred), px(P.illuminationSigmaMm));
    cv::Mat stddev;
    cv::sqrt(var + 1e-5, stddev);
    return cv::Mat(centred / stddev);
  };
  const cv::Mat raw = luminance(photo);
  cv::Mat closed;  // a new buffer: morphologyEx must not write into `raw`
  if (const int r = static_cast<int>(std::lround(px(P.poreClosingMm))); r < 1) {
    closed = raw;
  } else {
    const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1));
    cv::morphologyEx(raw, closed, cv::MORPH_CLOSE, disc, cv::Point(-1, -1), 1, cv::BORDER_REFLECT);
  }
  cv::Mat tone = closed;
  if (P.poreContrast > 0.0f && closed.data != raw.data) {
    // Pore density (black top-hat: what the closing filled), smoothed to a band and put back as
    // darkness, in luminance units: bands of pores read as dark bands, single pores do not.
    tone = closed - P.poreContrast * gaussian(closed - raw, px(P.poreDensitySigmaMm));
  }
  const cv::Mat flat = flatten(tone);
  progress.set(0.1);
  progress.throwIfCancelled();

  // 2. Structure tensor: ring normal (dominant gradient direction) and coherence.
  const cv::Mat pre = gaussian(flat, px(P.gradientSigmaMm));
  cv::Mat gx, gy;
  cv::Scharr(pre, gx, CV_32F, 1, 0, 1.0 / 32.0, 0, cv::BORDER_REFLECT);
  cv::Scharr(pre, gy, CV_32F, 0, 1, 1.0 / 32.0, 0, cv::BORDER_REFLECT);
  const float so = px(P.orientationSigmaMm);
  const cv::Mat jxx = gaussian(gx.mul(gx), so), jyy = gaussian(gy.mul(gy), so),
                jxy = gaussian(gx.mul(gy), so);
  cv::Mat nx(h, w, CV_32F), ny(h, w, CV_32F), coherence(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float a = jxx.at<float>(y, x), b = jyy.at<float>(y, x), c = jxy.at<float>(y, x);
      const float diff = std::sqrt((a - b) * (a - b) + 4 * c * c);
      coherence.at<float>(y, x) = diff / (a + b + 1e-12f);
      const float theta = 0.5f * std::atan2(2 * c, a - b);
      nx.at<float>(y, x) = std::cos(theta);
      ny.at<float>(y, x) = std::sin(theta);
    }
  orientNormals(nx, ny, coherence);
  progress.set(0.3);
  progress.throwIfCancelled();

  // 3. Smoothing along the rings: a Gaussian-weighted average along the streamline of the ring
  // direction through each pixel (following curved rings), after a small isotropic blur.
  const float sa = std::max(0.5f, px(P.alongSigmaMm));
  const int steps = std::max(1, static_cast<int>(std::ceil(2.5f * sa)));
  std::vector<float> weights(steps + 1);
  for (int k = 0; k <= steps; ++k) weights[k] = std::exp(-0.5f * k * k / (sa * sa));
  const auto alongRings = [&](const cv::Mat& image) {
    const cv::Mat base = gaussian(image, px(P.acrossSigmaMm));
    cv::Mat smooth(h, w, CV_32F);
    parallelRows(
        h,
        [&](int y) {
          for (int x = 0; x < w; ++x) {
            float sum = weights[0] * base.at<float>(y, x), weight = weights[0];
            for (int dir = -1; dir <= 1; dir += 2) {
              float cx = static_cast<float>(x), cy = static_cast<float>(y);
              float tx = -ny.at<float>(y, x) * dir, ty = nx.at<float>(y, x) * dir;
              for (int k = 1; k <= steps; ++k) {
                cx += tx;
                cy += ty;
                if (cx < 0 || cy < 0 || cx > w - 1 || cy > h - 1) break;
                sum += weights[k] * sample(base, cx, cy);
                weight += weights[k];
                const int ix = static_cast<int>(cx + 0.5f), iy = static_cast<int>(cy + 0.5f);
                float ux = -ny.at<float>(iy, ix), uy = nx.at<float>(iy, ix);
                if (ux * tx + uy * ty < 0) {
                  ux = -ux;
                  uy = -uy;
                }
                tx = ux;
                ty = uy;
              }
            }
            smooth.at<float>(y, x) = sum / weight;
          }
        },
        rowsOnly);
    return smooth;
  };
  // 4. Signed derivative across the rings (along the propagated normal).
  const float step = std::max(0.7f, px(P.derivativeStepMm));
  const auto across = [&](const cv::Mat& smooth) {
    cv::Mat deriv(h, w, CV_32F);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float ax = nx.at<float>(y, x) * step, ay = ny.at<float>(y, x) * step;
        deriv.at<float>(y, x) = sample(smooth, x + ax, y + ay) - sample(smooth, x - ax, y - ay);
      }
    return deriv;
  };
  const cv::Mat deriv = across(alongRings(flat));
  // The polarity is judged on the photo before the pore closing when asked (the pores mark the
  // earlywood side of ring-porous boundaries).
  const cv::Mat polarityDeriv =
      P.polarityFromUnclosed && closed.data != raw.data ? across(alongRings(flatten(raw))) : deriv;
  progress.set(0.6);

  // Non-maximum suppression across the rings, for one sign of the derivative.
  const auto peaks = [&](int sign) {
    cv::Mat strength(h, w, CV_32F, cv::Scalar(0));
    for (int y = 1; y < h - 1; ++y)
      for (int x = 1; x < w - 1; ++x) {
        const float v = sign * deriv.at<float>(y, x);
        if (v < P.lowThreshold || coherence.at<float>(y, x) < P.minCoherence) continue;
        const float ax = nx.at<float>(y, x), ay = ny.at<float>(y, x);
        const float before = sign * sample(deriv, x - ax, y - ay);
        const float after = sign * sample(deriv, x + ax, y + ay);
        if (v >= after && v > before) strength.at<float>(y, x) = v;
      }
    return strength;
  };
  const cv::Mat rising = peaks(+1), falling = peaks(-1);
  // Sharpness of each sign: a ring's profile across is a sawtooth (slow change through the ring, a
  // step at the boundary), so the derivative is skewed towards the boundary's sign. Score of a sign:
  // the third moment of that sign's part of the derivative over coherent pixels.
  double cubes[2] = {0, 0};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (coherence.at<float>(y, x) < P.minCoherence) continue;
      const double d = polarityDeriv.at<float>(y, x);
      cubes[d > 0 ? 1 : 0] += std::abs(d * d * d);
    }
  const double total = std::max(1e-12, cubes[0] + cubes[1]);
  ClassicalRingResult result;
  result.sharpness[0] = static_cast<float>(cubes[0] / total);
  result.sharpness[1] = static_cast<float>(cubes[1] / total);
  cv::Mat candidates;
  switch (P.polarity) {
    case ClassicalRingParams::Polarity::Auto:
      result.chosenSign = result.sharpness[1] >= result.sharpness[0] ? 1 : -1;
      candidates = result.chosenSign > 0 ? rising : falling;
      break;
    case ClassicalRingParams::Polarity::Rising:
      result.chosenSign = 1;
      candidates = rising;
      break;
    case ClassicalRingParams::Polarity::Falling:
      result.chosenSign = -1;
      candidates = falling;
      break;
    case ClassicalRingParams::Polarity::Both:
      candidates = cv::max(rising, falling);
      break;
  }
  progress.set(0.75);
  progress.throwIfCancelled();

  // 5. Hysteresis and length: keep 8-connected curves that reach the high threshold and are long.
  cv::Mat candidateMask = candidates > 0;
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(candidateMask, labels, stats, centroids, 8, CV_32S);
  std::vector<float> peak(count, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = labels.at<int>(y, x);
      if (l > 0) peak[l] = std::max(peak[l], candidates.at<float>(y, x));
    }
  const int minLength = std::max(3, static_cast<int>(std::lround(px(P.minLengthMm))));
  cv::Mat boundary(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = labels.at<int>(y, x);
      if (l > 0 && peak[l] >= P.highThreshold && stats.at<int>(l, cv::CC_STAT_AREA) >= minLength)
        boundary.at<unsigned char>(y, x) = 1;
    }

  // 6. Ring width (twice the median distance between boundaries, measured on the medial ridges of the
  // distance map) and the Eq. 1 profile of the distance to the nearest boundary.
  cv::Mat notBoundary = boundary == 0;
  cv::Mat distance;
  cv::distanceTransform(notBoundary, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  std::vector<float> medial;
  const float maxWidth = px(P.maxRingWidthMm), minWidth = std::max(2.0f, px(P.minRingWidthMm));
  if (cv::countNonZero(boundary) > 0) {
    for (int y = 2; y < h - 2; ++y)
      for (int x = 2; x < w - 2; ++x) {
        const float d = distance.at<float>(y, x);
        if (d < 1.0f || 2 * d > maxWidth) continue;
        const float ax = nx.at<float>(y, x), ay = ny.at<float>(y, x);
        if (d >= sample(distance, x + ax, y + ay) && d >= sample(distance, x - ax, y - ay))
          medial.push_back(d);
      }
  }
  float width = px(3.0f);
  if (!medial.empty()) {
    std::nth_element(medial.begin(), medial.begin() + medial.size() / 2, medial.end());
    width = 2.0f * medial[medial.size() / 2];
  }
  width = std::clamp(width, minWidth, std::max(minWidth, maxWidth));
  result.ringWidthPx = width;

  cv::Mat arl(h, w, CV_32F);
  const bool any = cv::countNonZero(boundary) > 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!any) {
        arl.at<float>(y, x) = 0.0f;
        continue;
      }
      const float g = std::min(distance.at<float>(y, x) / width, 0.5f);
      arl.at<float>(y, x) = std::pow(0.5f * (std::cos(2.0f * std::numbers::pi_v<float> * g) + 1.0f), P.power);
    }
  result.arl = toImage(arl);
  cv::Mat boundaryF;
  boundary.convertTo(boundaryF, CV_32F);
  result.boundaries = toImage(boundaryF);
  result.coherence = toImage(coherence);
  progress.set(1.0);
  return result;
}

}  // namespace kerf
