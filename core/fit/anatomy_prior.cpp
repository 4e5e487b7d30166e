#include "fit/anatomy_prior.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace kerf {

namespace {

constexpr double kPi = std::numbers::pi;

// Log luminance of an image (Rec. 709 weights on RGB; grey as is), as a float matrix.
cv::Mat logLuminance(const Image& image) {
  cv::Mat out(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y) {
    float* row = out.ptr<float>(y);
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      const float l = image.channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
      row[x] = std::log(std::max(l, 0.0f) + 0.02f);
    }
  }
  return out;
}

}  // namespace

FaceAnatomy analyzeFaceTexture(const Image& image, const Block& block, FaceId face,
                               const AnatomyOptions& options) {
  FaceAnatomy result;
  const int border = std::max(0, options.borderPx);
  if (image.empty() || image.width <= 2 * border + 8 || image.height <= 2 * border + 8) return result;
  // 1. Band-pass at pore/fibre scale: DoG of the log luminance. The coarse Gaussian removes the rings
  // (several mm wide), figure and lighting gradients; the fine one pixel noise and JPEG blocking.
  const cv::Mat lum = logLuminance(image);
  cv::Mat fine, coarse;
  cv::GaussianBlur(lum, fine, cv::Size(), options.fineSigmaPx, options.fineSigmaPx, cv::BORDER_REFLECT);
  cv::GaussianBlur(lum, coarse, cv::Size(), options.coarseSigmaPx, options.coarseSigmaPx, cv::BORDER_REFLECT);
  const cv::Mat band = fine - coarse;
  // 2. Structure tensor: gradient products integrated over tensorSigmaPx.
  cv::Mat gx, gy;
  cv::Sobel(band, gx, CV_32F, 1, 0, 3, 1.0, 0.0, cv::BORDER_REFLECT);
  cv::Sobel(band, gy, CV_32F, 0, 1, 3, 1.0, 0.0, cv::BORDER_REFLECT);
  cv::Mat jxx = gx.mul(gx), jyy = gy.mul(gy), jxy = gx.mul(gy);
  const cv::Size k;
  cv::GaussianBlur(jxx, jxx, k, options.tensorSigmaPx, options.tensorSigmaPx, cv::BORDER_REFLECT);
  cv::GaussianBlur(jyy, jyy, k, options.tensorSigmaPx, options.tensorSigmaPx, cv::BORDER_REFLECT);
  cv::GaussianBlur(jxy, jxy, k, options.tensorSigmaPx, options.tensorSigmaPx, cv::BORDER_REFLECT);
  // 3. Per pixel: doubled-angle vector of the dominant gradient orientation, scaled by the local
  // coherence (l1 - l2) / (l1 + l2) = |(jxx - jyy, 2 jxy)| / (jxx + jyy). Summing unit-free vectors
  // counts pixels rather than gradient energy, so a few strong edges (ring boundaries, cracks, the
  // block edge) cannot outvote the pore texture that covers the whole face.
  double sc = 0, ss = 0;
  long count = 0;
  for (int y = border; y < image.height - border; ++y) {
    const float* a = jxx.ptr<float>(y);
    const float* b = jyy.ptr<float>(y);
    const float* c = jxy.ptr<float>(y);
    for (int x = border; x < image.width - border; ++x) {
      const double trace = static_cast<double>(a[x]) + b[x];
      ++count;
      if (trace <= 1e-12) continue;
      sc += (a[x] - b[x]) / trace;  // coherence * cos(2 theta)
      ss += 2.0 * c[x] / trace;     // coherence * sin(2 theta)
    }
  }
  if (count == 0) return result;
  sc /= static_cast<double>(count);
  ss /= static_cast<double>(count);
  result.present = true;
  result.anisotropy = static_cast<float>(std::hypot(sc, ss));
  // theta: the dominant gradient direction; the streaks run perpendicular to it.
  const double theta = 0.5 * std::atan2(ss, sc);
  double streak = theta + 0.5 * kPi;
  if (streak >= kPi) streak -= kPi;
  result.streakAngleDeg = static_cast<float>(streak * 180.0 / kPi);
  const FaceFrame fr = block.face(face);
  result.streak = glm::normalize(static_cast<float>(std::cos(streak)) * fr.right +
                                 static_cast<float>(std::sin(streak)) * fr.down);
  return result;
}

AnatomyEstimate estimateFibreDirection(const std::array<Image, 6>& photos, const Block& block,
                                       const AnatomyOptions& options) {
  AnatomyEstimate est;
  float maxAniso = 0;
  for (FaceId f : kAllFaces) {
    est.faces[faceIndex(f)] = analyzeFaceTexture(photos[faceIndex(f)], block, f, options);
    if (est.faces[faceIndex(f)].present) {
      ++est.facesUsed;
      maxAniso = std::max(maxAniso, est.faces[faceIndex(f)].anisotropy);
    }
  }
  if (est.facesUsed == 0) throw InputError("no usable face photo to estimate the fibre direction from");
  // Orientation tensor: side-grain streak votes plus end-grain votes along the normals of the faces that
  // are clearly less anisotropic than the most streaked one.
  cv::Matx33d m = cv::Matx33d::zeros();
  for (FaceId f : kAllFaces) {
    const FaceAnatomy& fa = est.faces[faceIndex(f)];
    if (!fa.present) continue;
    const cv::Vec3d s(fa.streak.x, fa.streak.y, fa.streak.z);
    m += fa.anisotropy * (s * s.t());
    const glm::vec3 n = block.face(f).normal;
    const cv::Vec3d nv(n.x, n.y, n.z);
    m += std::max(0.0f, options.endGrainWeight * (maxAniso - fa.anisotropy)) * (nv * nv.t());
  }
  cv::Mat values, vectors;
  cv::eigen(cv::Mat(m), values, vectors);  // descending eigenvalues, eigenvectors as rows
  for (int i = 0; i < 3; ++i) est.eigenvalues[i] = static_cast<float>(values.at<double>(i));
  glm::vec3 fibre(static_cast<float>(vectors.at<double>(0, 0)), static_cast<float>(vectors.at<double>(0, 1)),
                  static_cast<float>(vectors.at<double>(0, 2)));
  fibre = glm::normalize(fibre);
  if (fibre.y < 0 || (fibre.y == 0 && (fibre.x < 0 || (fibre.x == 0 && fibre.z < 0)))) fibre = -fibre;
  est.fibre = fibre;
  const double sum = std::max(1e-12, values.at<double>(0) + values.at<double>(1) + values.at<double>(2));
  est.confidence =
      static_cast<float>(std::clamp((values.at<double>(0) - values.at<double>(1)) / sum, 0.0, 1.0));
  return est;
}

double anatomyPenalty(const AnatomyEstimate& estimate, glm::vec3 direction) {
  const float len = glm::length(direction);
  if (len <= 0) return estimate.confidence;
  const double c = glm::dot(direction / len, estimate.fibre);
  return estimate.confidence * (1.0 - c * c);
}

double anatomyAngleDeg(const AnatomyEstimate& estimate, glm::vec3 direction) {
  const float len = glm::length(direction);
  if (len <= 0) return 90.0;
  const double c = std::abs(glm::dot(direction / len, estimate.fibre));
  return std::acos(std::min(1.0, c)) * 180.0 / kPi;
}

}  // namespace kerf
