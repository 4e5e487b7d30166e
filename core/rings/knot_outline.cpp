#include "rings/knot_outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace kerf {

namespace {

cv::Mat luminanceOf(const Image& photo) {
  cv::Mat out(photo.height, photo.width, CV_32F);
  for (int y = 0; y < photo.height; ++y) {
    float* row = out.ptr<float>(y);
    for (int x = 0; x < photo.width; ++x) {
      const float* p = photo.pixel(x, y);
      row[x] = photo.channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
    }
  }
  return out;
}

float median(std::vector<float> v) {
  if (v.empty()) return 0.0f;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The photo on rays from the mark: row a is the ray at angle 2 pi a / rays, column r at (r + 0.5) px.
struct Polar {
  cv::Mat values, valid;
  float pxPerColumn = 1;
};

Polar polarAround(const cv::Mat& luminance, cv::Point2f centre, float radiusPx, int rays) {
  Polar out;
  const int columns = std::max(8, static_cast<int>(std::ceil(radiusPx)));
  out.pxPerColumn = radiusPx / static_cast<float>(columns);
  const int flags = cv::INTER_LINEAR | cv::WARP_FILL_OUTLIERS | cv::WARP_POLAR_LINEAR;
  cv::warpPolar(luminance, out.values, {columns, rays}, centre, radiusPx, flags);
  const cv::Mat ones(luminance.size(), CV_32F, cv::Scalar(1.0f));
  cv::warpPolar(ones, out.valid, {columns, rays}, centre, radiusPx,
                cv::INTER_NEAREST | cv::WARP_FILL_OUTLIERS);
  return out;
}

struct EdgePoint {
  cv::Point2f px;
  int ray;
};

// On each ray, where the brightness first climbs to `threshold` and stays above it for holdColumns.
std::vector<EdgePoint> edgesOnRays(const Polar& polar, cv::Point2f centre, float threshold, int holdColumns) {
  std::vector<EdgePoint> out;
  const int rays = polar.values.rows, columns = polar.values.cols;
  for (int a = 0; a < rays; ++a) {
    const float* v = polar.values.ptr<float>(a);
    const float* ok = polar.valid.ptr<float>(a);
    double ahead = 0;  // sum of v over [r, r + holdColumns)
    for (int r = 0; r < std::min(holdColumns, columns); ++r) ahead += v[r];
    for (int r = 1; r + holdColumns < columns; ++r) {
      ahead += v[r + holdColumns - 1] - v[r - 1];
      if (ok[r + holdColumns] < 0.5f) break;  // the ray leaves the photo before the edge is sure
      if (v[r] < threshold || ahead < threshold * holdColumns) continue;
      const float t = (threshold - v[r - 1]) / std::max(v[r] - v[r - 1], 1e-6f);
      const float radius = (static_cast<float>(r - 1) + std::clamp(t, 0.0f, 1.0f) + 0.5f) * polar.pxPerColumn;
      const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(a) / static_cast<float>(rays);
      out.push_back({centre + radius * cv::Point2f(std::cos(angle), std::sin(angle)), a});
      break;
    }
  }
  return out;
}

// |(p - centre)| in units of the ellipse's radius in p's direction: 1 on the ellipse.
float ellipseRadiusRatio(const cv::RotatedRect& e, cv::Point2f p) {
  const float angle = e.angle * std::numbers::pi_v<float> / 180.0f;
  const cv::Point2f d = p - e.center;
  const float u = (d.x * std::cos(angle) + d.y * std::sin(angle)) / std::max(0.5f * e.size.width, 1e-3f);
  const float w = (-d.x * std::sin(angle) + d.y * std::cos(angle)) / std::max(0.5f * e.size.height, 1e-3f);
  return std::sqrt(u * u + w * w);
}

// cv::fitEllipse on the points, then again on those within `tolerance` of it (three rounds).
std::vector<EdgePoint> trimmedEllipse(std::vector<EdgePoint> points, float tolerance,
                                      cv::RotatedRect& ellipse) {
  for (int round = 0; round < 3 && points.size() >= 6; ++round) {
    std::vector<cv::Point2f> xy;
    for (const EdgePoint& p : points) xy.push_back(p.px);
    ellipse = cv::fitEllipse(xy);
    std::vector<EdgePoint> kept;
    for (const EdgePoint& p : points)
      if (std::abs(ellipseRadiusRatio(ellipse, p.px) - 1.0f) <= tolerance) kept.push_back(p);
    if (kept.size() == points.size()) break;
    points = std::move(kept);
  }
  return points;
}

// Luminance medians inside (ratio < inner) and around (ratio in [lo, hi]) the ellipse.
void levelsAround(const cv::Mat& luminance, const cv::RotatedRect& e, float& knot, float& wood) {
  const cv::Rect box = cv::Rect(cv::RotatedRect(e.center, e.size * 2.0f, e.angle).boundingRect()) &
                       cv::Rect(0, 0, luminance.cols, luminance.rows);
  std::vector<float> inside, around;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) {
      const float q = ellipseRadiusRatio(e, cv::Point2f(static_cast<float>(x), static_cast<float>(y)));
      if (q < 0.6f)
        inside.push_back(luminance.at<float>(y, x));
      else if (q > 1.3f && q < 2.0f)
        around.push_back(luminance.at<float>(y, x));
    }
  if (!inside.empty()) knot = median(std::move(inside));
  if (!around.empty()) wood = median(std::move(around));
}

std::string mm(float v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", static_cast<double>(v));
  return buffer;
}

}  // namespace

KnotOutline detectKnotOutline(const Image& photo, const Block& block, const KnotMark& mark,
                              const KnotOutlineOptions& options) {
  KnotOutline out;
  out.knot = mark.knot;
  out.face = mark.face;
  out.seed = mark.point;
  if (photo.empty()) {
    out.note = "no photo of the face";
    return out;
  }
  const glm::ivec2 size(photo.width, photo.height);
  const glm::vec2 faceMm = faceSizeMm(block, mark.face);
  const glm::vec2 pxPerMm = glm::vec2(size) / faceMm;
  const float pxMm = 0.5f * (pxPerMm.x + pxPerMm.y);
  // Kerf's pixel centres are at +0.5, OpenCV's at 0.
  const glm::vec2 at = faceMmToImage(block, mark.face, mark.point, size) - 0.5f;
  cv::Point2f centre(at.x, at.y);
  if (at.x < 0 || at.y < 0 || at.x > static_cast<float>(size.x - 1) ||
      at.y > static_cast<float>(size.y - 1)) {
    out.note = "the mark lies off the photo";
    return out;
  }
  const cv::Mat luminance = luminanceOf(photo);
  const float radiusPx = options.maxRadiusMm * pxMm;
  // The photo on rays from `from`, a little smoothed: 0.3 mm along the rays (noise, pores), two rays
  // across (4 degrees).
  const auto raysFrom = [&](cv::Point2f from) {
    Polar polar = polarAround(luminance, from, radiusPx, options.rays);
    cv::GaussianBlur(polar.values, polar.values, cv::Size(0, 0),
                     std::max(0.3f * pxMm / polar.pxPerColumn, 0.5f), 1.0, cv::BORDER_REPLICATE);
    return polar;
  };
  Polar polar = raysFrom(centre);
  std::vector<float> core, wood;
  const int coreColumns = std::max(1, static_cast<int>(options.coreRadiusMm * pxMm / polar.pxPerColumn));
  for (int a = 0; a < polar.values.rows; ++a)
    for (int r = 0; r < std::min(coreColumns, polar.values.cols); ++r)
      if (polar.valid.at<float>(a, r) > 0.5f) core.push_back(polar.values.at<float>(a, r));
  for (int y = 0; y < luminance.rows; ++y)
    for (int x = 0; x < luminance.cols; ++x) wood.push_back(luminance.at<float>(y, x));
  out.knotLevel = median(std::move(core));
  out.woodLevel = median(std::move(wood));
  const int hold = std::max(2, static_cast<int>(std::lround(options.holdMm * pxMm / polar.pxPerColumn)));
  const auto minRays = static_cast<std::size_t>(options.minRayShare * static_cast<float>(options.rays));

  // Pass 0 from the mark gives a first ellipse (a mark near the knot's edge sees much of it from the
  // side); pass 1 traces again from that ellipse's centre, with the levels measured inside and around it.
  cv::RotatedRect ellipse;
  std::vector<EdgePoint> edge;
  for (int pass = 0; pass < 2; ++pass) {
    if (out.woodLevel - out.knotLevel < options.minContrast) {
      out.note = "the wood at the mark is not darker than around it (knot " + mm(100 * out.knotLevel) +
                 " %, wood " + mm(100 * out.woodLevel) + " % luminance): no knot edge seen";
      return out;
    }
    const float threshold = 0.5f * (out.knotLevel + out.woodLevel);
    const std::vector<EdgePoint> found = edgesOnRays(polar, centre, threshold, hold);
    out.rays = static_cast<int>(found.size());
    const std::size_t needed = pass == 0 ? std::max<std::size_t>(6, minRays / 3) : minRays;
    if (found.size() < needed) {
      out.note = "an edge on " + std::to_string(found.size()) + " of " + std::to_string(options.rays) +
                 " rays only (the knot runs off the photo, or is not darker all round)";
      return out;
    }
    edge = trimmedEllipse(found, options.inlierTolerance, ellipse);
    if (edge.size() < needed) {
      out.note = "the edge points do not lie on an ellipse (" + std::to_string(edge.size()) + " of " +
                 std::to_string(found.size()) + " agree)";
      return out;
    }
    if (pass == 1) break;
    levelsAround(luminance, ellipse, out.knotLevel, out.woodLevel);
    if (ellipse.center.x >= 0 && ellipse.center.y >= 0 &&
        ellipse.center.x <= static_cast<float>(size.x - 1) &&
        ellipse.center.y <= static_cast<float>(size.y - 1)) {
      centre = ellipse.center;
      polar = raysFrom(centre);
    }
  }
  const float a = 0.5f * ellipse.size.width / pxMm, b = 0.5f * ellipse.size.height / pxMm;
  const float meanRadius = 0.5f * (a + b);
  const glm::vec2 centreMm =
      imageToFaceMm(block, mark.face, {ellipse.center.x + 0.5f, ellipse.center.y + 0.5f}, size);
  if (glm::length(centreMm - mark.point) > meanRadius) {
    out.note = "the dark ellipse found (" + mm(2 * meanRadius) + " mm) does not hold the mark";
    return out;
  }
  out.found = true;
  out.center = centreMm;
  const float angle = ellipse.angle * std::numbers::pi_v<float> / 180.0f;
  out.semiAxesMm = a >= b ? glm::vec2(a, b) : glm::vec2(b, a);
  out.angleRad = a >= b ? angle : angle + 0.5f * std::numbers::pi_v<float>;
  for (const EdgePoint& p : edge)
    out.edge.push_back(imageToFaceMm(block, mark.face, {p.px.x + 0.5f, p.px.y + 0.5f}, size));
  out.note = mm(2 * out.semiAxesMm.x) + " x " + mm(2 * out.semiAxesMm.y) + " mm, edge on " +
             std::to_string(edge.size()) + " of " + std::to_string(options.rays) + " rays";
  return out;
}

std::vector<KnotOutline> detectKnotOutlines(const std::array<Image, 6>& photos, const Block& block,
                                            const std::vector<KnotMark>& marks,
                                            const KnotOutlineOptions& options) {
  std::vector<KnotOutline> out;
  out.reserve(marks.size());
  for (const KnotMark& m : marks) {
    if (m.ignoreEdge) {
      KnotOutline ignored;
      ignored.knot = m.knot;
      ignored.face = m.face;
      ignored.seed = m.point;
      ignored.note = "its edge on the photo is ignored (the mark says so)";
      out.push_back(std::move(ignored));
      continue;
    }
    out.push_back(detectKnotOutline(photos[faceIndex(m.face)], block, m, options));
  }
  return out;
}

}  // namespace kerf
