#include "rings/annotations.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <set>

#include "rings/contours.hpp"
#include "util/error.hpp"

namespace kerf {
namespace fs = std::filesystem;

int Annotations::nextKnotId() const {
  int next = 0;
  for (const KnotMark& mark : knots) next = std::max(next, mark.knot + 1);
  return next;
}

// --- Coordinates ---------------------------------------------------------------------------------

glm::vec2 faceSizeMm(const Block& block, FaceId face) {
  const FaceFrame f = block.face(face);
  return {f.widthMm, f.heightMm};
}

glm::vec3 faceMmToBlock(const Block& block, FaceId face, glm::vec2 q) {
  const FaceFrame f = block.face(face);
  return f.center + (q.x - 0.5f * f.widthMm) * f.right + (q.y - 0.5f * f.heightMm) * f.down;
}

glm::vec2 blockToFaceMm(const Block& block, FaceId face, glm::vec3 p) {
  const FaceFrame f = block.face(face);
  const glm::vec3 d = p - f.center;
  return {glm::dot(d, f.right) + 0.5f * f.widthMm, glm::dot(d, f.down) + 0.5f * f.heightMm};
}

glm::vec2 faceMmToImage(const Block& block, FaceId face, glm::vec2 q, glm::ivec2 size) {
  const glm::vec2 mm = faceSizeMm(block, face);
  return {q.x / mm.x * size.x, q.y / mm.y * size.y};
}

glm::vec2 imageToFaceMm(const Block& block, FaceId face, glm::vec2 pos, glm::ivec2 size) {
  const glm::vec2 mm = faceSizeMm(block, face);
  return {pos.x / size.x * mm.x, pos.y / size.y * mm.y};
}

std::vector<glm::vec3> traceToBlock(const RingTrace& trace, const Block& block) {
  std::vector<glm::vec3> out;
  out.reserve(trace.points.size());
  for (glm::vec2 q : trace.points) out.push_back(faceMmToBlock(block, trace.face, q));
  return out;
}

// --- Polylines -----------------------------------------------------------------------------------

std::optional<PolylineHit> nearestOnPolyline(const std::vector<glm::vec2>& line, glm::vec2 p) {
  if (line.size() < 2) return std::nullopt;
  PolylineHit best;
  best.distance = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const glm::vec2 a = line[i], d = line[i + 1] - a;
    const float len2 = glm::dot(d, d);
    const float t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
    const glm::vec2 q = a + t * d;
    const float dist = glm::length(p - q);
    if (dist < best.distance) best = {i, t, q, dist};
  }
  return best;
}

float polylineLength(const std::vector<glm::vec2>& line) {
  float length = 0;
  for (std::size_t i = 1; i < line.size(); ++i) length += glm::length(line[i] - line[i - 1]);
  return length;
}

std::vector<glm::vec2> resamplePolyline(const std::vector<glm::vec2>& line, float spacing) {
  if (line.size() < 2 || !(spacing > 0)) return line;
  const float total = polylineLength(line);
  if (total <= 0) return {line.front(), line.back()};
  const int steps = std::max(1, static_cast<int>(std::ceil(total / spacing - 1e-4f)));
  const float step = total / steps;  // equal gaps that add up to the length
  std::vector<glm::vec2> out{line.front()};
  std::size_t segment = 0;
  float segmentStart = 0;  // arc length at line[segment]
  for (int k = 1; k < steps; ++k) {
    const float s = k * step;
    while (segment + 1 < line.size() - 1 &&
           segmentStart + glm::length(line[segment + 1] - line[segment]) < s) {
      segmentStart += glm::length(line[segment + 1] - line[segment]);
      ++segment;
    }
    const float len = glm::length(line[segment + 1] - line[segment]);
    const float t = len > 0 ? std::clamp((s - segmentStart) / len, 0.0f, 1.0f) : 0.0f;
    out.push_back(line[segment] + t * (line[segment + 1] - line[segment]));
  }
  out.push_back(line.back());
  return out;
}

namespace {

void simplifyRange(const std::vector<glm::vec2>& line, std::size_t first, std::size_t last, float tol,
                   std::vector<bool>& keep) {
  if (last <= first + 1) return;
  const glm::vec2 a = line[first], d = line[last] - a;
  const float len = glm::length(d);
  float worst = -1;
  std::size_t worstIndex = first;
  for (std::size_t i = first + 1; i < last; ++i) {
    const glm::vec2 v = line[i] - a;
    const float dist = len > 0 ? std::abs(d.x * v.y - d.y * v.x) / len : glm::length(v);
    if (dist > worst) worst = dist, worstIndex = i;
  }
  if (worst <= tol) return;
  keep[worstIndex] = true;
  simplifyRange(line, first, worstIndex, tol, keep);
  simplifyRange(line, worstIndex, last, tol, keep);
}

}  // namespace

std::vector<glm::vec2> simplifyPolyline(const std::vector<glm::vec2>& line, float tol) {
  if (line.size() < 3) return line;
  std::vector<bool> keep(line.size(), false);
  keep.front() = keep.back() = true;
  simplifyRange(line, 0, line.size() - 1, tol, keep);
  std::vector<glm::vec2> out;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (keep[i]) out.push_back(line[i]);
  return out;
}

std::vector<glm::vec2> smoothPolyline(const std::vector<glm::vec2>& line, float spacing, float sigma) {
  if (line.size() < 2) return line;
  const std::vector<glm::vec2> even = resamplePolyline(line, spacing);
  const int n = static_cast<int>(even.size());
  if (n < 3 || !(sigma > 0)) return even;
  const float step = polylineLength(even) / (n - 1);
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0f * sigma / std::max(step, 1e-6f))));
  // Odd reflection through the end points (p[-k] = 2 p[0] - p[k]) extends the stroke linearly, so a
  // straight stroke stays straight and the ends stay where they were drawn.
  const auto at = [&](int i) -> glm::vec2 {
    if (i < 0) return 2.0f * even.front() - even[std::min(-i, n - 1)];
    if (i >= n) return 2.0f * even.back() - even[std::max(2 * (n - 1) - i, 0)];
    return even[i];
  };
  std::vector<float> weights(radius + 1);
  for (int k = 0; k <= radius; ++k) weights[k] = std::exp(-0.5f * (k * step / sigma) * (k * step / sigma));
  std::vector<glm::vec2> smooth(n);
  for (int i = 0; i < n; ++i) {
    glm::vec2 sum(0.0f);
    float total = 0;
    for (int k = -radius; k <= radius; ++k) {
      sum += weights[std::abs(k)] * at(i + k);
      total += weights[std::abs(k)];
    }
    smooth[i] = sum / total;
  }
  smooth.front() = even.front();
  smooth.back() = even.back();
  return resamplePolyline(smooth, spacing);
}

// --- Edits ---------------------------------------------------------------------------------------

std::optional<std::pair<RingTrace, RingTrace>> splitTrace(const RingTrace& trace, glm::vec2 at,
                                                          float minPiece) {
  const auto hit = nearestOnPolyline(trace.points, at);
  if (!hit) return std::nullopt;
  const auto& pts = trace.points;
  float before = 0;
  for (std::size_t i = 0; i < hit->segment; ++i) before += glm::length(pts[i + 1] - pts[i]);
  before += glm::length(hit->point - pts[hit->segment]);
  const float total = polylineLength(pts);
  if (before < minPiece || total - before < minPiece) return std::nullopt;
  RingTrace first = trace, second = trace;
  first.points.assign(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(hit->segment) + 1);
  second.points.assign(pts.begin() + static_cast<std::ptrdiff_t>(hit->segment) + 1, pts.end());
  constexpr float kSame = 1e-5f;
  if (glm::length(first.points.back() - hit->point) > kSame) first.points.push_back(hit->point);
  if (glm::length(second.points.front() - hit->point) > kSame)
    second.points.insert(second.points.begin(), hit->point);
  else
    second.points.front() = hit->point;
  if (first.points.size() < 2 || second.points.size() < 2) return std::nullopt;
  return std::make_pair(std::move(first), std::move(second));
}

std::optional<RingTrace> joinTraces(const RingTrace& a, const RingTrace& b) {
  if (a.face != b.face || a.points.empty() || b.points.empty()) return std::nullopt;
  const float d[4] = {glm::length(a.points.back() - b.points.front()),    // a + b
                      glm::length(a.points.back() - b.points.back()),     // a + reversed b
                      glm::length(a.points.front() - b.points.back()),    // b + a
                      glm::length(a.points.front() - b.points.front())};  // reversed b + a
  const int best = static_cast<int>(std::min_element(d, d + 4) - d);
  std::vector<glm::vec2> bp = b.points;
  if (best == 1 || best == 3) std::reverse(bp.begin(), bp.end());
  RingTrace joined = a;
  joined.year = a.year ? a.year : b.year;
  joined.origin = TraceOrigin::Drawn;
  std::vector<glm::vec2> head = best <= 1 ? a.points : bp;
  const std::vector<glm::vec2>& tail = best <= 1 ? bp : a.points;
  const bool touching = glm::length(head.back() - tail.front()) < 1e-5f;
  head.insert(head.end(), tail.begin() + (touching ? 1 : 0), tail.end());
  joined.points = std::move(head);
  return joined;
}

namespace {

std::vector<std::size_t> validIndices(const Annotations& annotations, std::vector<std::size_t> indices) {
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::erase_if(indices, [&](std::size_t i) { return i >= annotations.traces.size(); });
  return indices;
}

}  // namespace

Annotations removeTraces(const Annotations& annotations, const std::vector<std::size_t>& indices) {
  const std::vector<std::size_t> remove = validIndices(annotations, indices);
  Annotations out = annotations;
  for (auto it = remove.rbegin(); it != remove.rend(); ++it)
    out.traces.erase(out.traces.begin() + static_cast<std::ptrdiff_t>(*it));
  return out;
}

Annotations splitTraceAt(const Annotations& annotations, std::size_t index, glm::vec2 at) {
  if (index >= annotations.traces.size()) return annotations;
  auto pieces = splitTrace(annotations.traces[index], at);
  if (!pieces) return annotations;
  Annotations out = annotations;
  out.traces[index] = std::move(pieces->first);
  out.traces.push_back(std::move(pieces->second));
  return out;
}

Annotations joinTracesAt(const Annotations& annotations, const std::vector<std::size_t>& indices) {
  // Keep the caller's order for "first", but drop duplicates and bad indices.
  std::vector<std::size_t> order;
  for (std::size_t i : indices)
    if (i < annotations.traces.size() && std::find(order.begin(), order.end(), i) == order.end())
      order.push_back(i);
  if (order.size() < 2) return annotations;
  const FaceId face = annotations.traces[order.front()].face;
  for (std::size_t i : order)
    if (annotations.traces[i].face != face || annotations.traces[i].points.empty()) return annotations;
  RingTrace joined = annotations.traces[order.front()];
  std::vector<std::size_t> rest(order.begin() + 1, order.end());
  while (!rest.empty()) {
    // The remaining trace with an end nearest to either end of what is joined so far.
    std::size_t bestK = 0;
    float bestD = std::numeric_limits<float>::max();
    for (std::size_t k = 0; k < rest.size(); ++k) {
      const auto& p = annotations.traces[rest[k]].points;
      for (glm::vec2 end : {joined.points.front(), joined.points.back()})
        for (glm::vec2 other : {p.front(), p.back()})
          if (glm::length(end - other) < bestD) bestD = glm::length(end - other), bestK = k;
    }
    joined = *joinTraces(joined, annotations.traces[rest[bestK]]);
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(bestK));
  }
  Annotations out = annotations;
  out.traces[order.front()] = std::move(joined);
  std::vector<std::size_t> remove(order.begin() + 1, order.end());
  return removeTraces(out, remove);
}

Annotations setYears(const Annotations& annotations, const std::vector<std::size_t>& indices,
                     std::optional<int> year) {
  Annotations out = annotations;
  for (std::size_t i : validIndices(annotations, indices)) {
    out.traces[i].year = year;
    if (year) out.traces[i].origin = TraceOrigin::Drawn;
  }
  return out;
}

Annotations offsetYears(const Annotations& annotations, const std::vector<std::size_t>& indices, int offset) {
  Annotations out = annotations;
  for (std::size_t i : validIndices(annotations, indices))
    if (out.traces[i].year) *out.traces[i].year += offset;
  return out;
}

Annotations replaceDetectedTraces(const Annotations& annotations, std::vector<RingTrace> detected) {
  Annotations out = annotations;
  std::erase_if(out.traces, [](const RingTrace& t) { return t.origin == TraceOrigin::Detected; });
  for (RingTrace& trace : detected) {
    trace.origin = TraceOrigin::Detected;
    out.traces.push_back(std::move(trace));
  }
  return out;
}

std::vector<RingTrace> tracesFromContours(const std::vector<FaceContour>& contours, const Block& block,
                                          glm::ivec2 imageSize, float simplifyPx) {
  std::vector<RingTrace> out;
  for (const FaceContour& contour : contours) {
    if (contour.pixels.size() < 2) continue;
    RingTrace trace;
    trace.face = contour.face;
    trace.origin = TraceOrigin::Detected;
    std::vector<glm::vec2> pts;
    pts.reserve(contour.pixels.size());
    for (glm::ivec2 p : contour.pixels)
      pts.push_back(imageToFaceMm(block, contour.face, glm::vec2(p) + 0.5f, imageSize));
    const float mmPerPx = faceSizeMm(block, contour.face).x / imageSize.x;
    trace.points = simplifyPolyline(pts, simplifyPx * mmPerPx);
    out.push_back(std::move(trace));
  }
  return out;
}

// --- Mokume images --------------------------------------------------------------------------------

namespace {

// Zhang-Suen thinning of a 0/1 mask (in place): strokes become one pixel wide, 8-connected.
void thin(cv::Mat& m) {
  const auto px = [&](int x, int y) -> int {
    return x >= 0 && y >= 0 && x < m.cols && y < m.rows ? m.at<unsigned char>(y, x) : 0;
  };
  bool changed = true;
  std::vector<cv::Point> remove;
  while (changed) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      remove.clear();
      for (int y = 0; y < m.rows; ++y)
        for (int x = 0; x < m.cols; ++x) {
          if (!m.at<unsigned char>(y, x)) continue;
          // Neighbours P2..P9, clockwise from north.
          const int p[8] = {px(x, y - 1), px(x + 1, y - 1), px(x + 1, y), px(x + 1, y + 1),
                            px(x, y + 1), px(x - 1, y + 1), px(x - 1, y), px(x - 1, y - 1)};
          int b = 0, a = 0;
          for (int k = 0; k < 8; ++k) {
            b += p[k];
            a += p[k] == 0 && p[(k + 1) % 8] == 1;
          }
          if (b < 2 || b > 6 || a != 1) continue;
          const bool c1 = pass == 0 ? !(p[0] && p[2] && p[4]) : !(p[0] && p[2] && p[6]);
          const bool c2 = pass == 0 ? !(p[2] && p[4] && p[6]) : !(p[0] && p[4] && p[6]);
          if (c1 && c2) remove.emplace_back(x, y);
        }
      for (const cv::Point& q : remove) m.at<unsigned char>(q) = 0;
      changed |= !remove.empty();
    }
  }
}

// Links the pixels of a one-pixel-wide mask into polylines of pixel indices.
std::vector<std::vector<cv::Point>> linkPixels(const cv::Mat& m) {
  const int dx[8] = {1, 0, -1, 0, 1, -1, -1, 1};  // 4-neighbours first: no diagonal short cuts
  const int dy[8] = {0, 1, 0, -1, 1, 1, -1, -1};
  const auto on = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < m.cols && y < m.rows && m.at<unsigned char>(y, x);
  };
  const auto degree = [&](int x, int y) {
    int n = 0;
    for (int k = 0; k < 8; ++k) n += on(x + dx[k], y + dy[k]);
    return n;
  };
  cv::Mat visited = cv::Mat::zeros(m.size(), CV_8UC1);
  std::vector<std::vector<cv::Point>> lines;
  const auto walk = [&](cv::Point start) {
    std::vector<cv::Point> line{start};
    visited.at<unsigned char>(start) = 1;
    cv::Point cur = start;
    for (;;) {
      bool moved = false;
      for (int k = 0; k < 8 && !moved; ++k) {
        const cv::Point next(cur.x + dx[k], cur.y + dy[k]);
        if (on(next.x, next.y) && !visited.at<unsigned char>(next)) {
          visited.at<unsigned char>(next) = 1;
          line.push_back(next);
          cur = next;
          moved = true;
        }
      }
      if (!moved) break;
    }
    // Reattach to a junction or close a loop: a visited neighbour that is not the previous point.
    if (line.size() >= 3) {
      for (int k = 0; k < 8; ++k) {
        const cv::Point next(cur.x + dx[k], cur.y + dy[k]);
        if (on(next.x, next.y) && next != line[line.size() - 2] && next != line[line.size() - 3] &&
            (next == line.front() || std::find(line.begin(), line.end(), next) == line.end())) {
          line.push_back(next);
          break;
        }
      }
    }
    lines.push_back(std::move(line));
  };
  // Strokes from their ends first, then what is left (closed loops).
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      if (on(x, y) && !visited.at<unsigned char>(y, x) && degree(x, y) == 1) walk({x, y});
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      if (on(x, y) && !visited.at<unsigned char>(y, x)) walk({x, y});
  return lines;
}

cv::Mat toMat(const GrayImage8& image) {
  return cv::Mat(image.height, image.width, CV_8UC1, const_cast<unsigned char*>(image.pixels.data()));
}

GrayImage8 fromMat(const cv::Mat& m) {
  GrayImage8 out;
  out.width = m.cols;
  out.height = m.rows;
  out.pixels.assign(m.datastart, m.dataend);
  return out;
}

}  // namespace

std::vector<RingTrace> ringTracesFromImage(const GrayImage8& image, FaceId face, const Block& block,
                                           int minPixels) {
  std::vector<RingTrace> out;
  if (image.empty()) return out;
  const glm::ivec2 size(image.width, image.height);
  std::set<int> values(image.pixels.begin(), image.pixels.end());
  values.erase(255);
  const cv::Mat src = toMat(image);
  const float mmPerPx = faceSizeMm(block, face).x / size.x;
  for (int value : values) {
    cv::Mat mask = (src == value) / 255;  // 0/1
    thin(mask);
    for (const auto& line : linkPixels(mask)) {
      if (static_cast<int>(line.size()) < minPixels) continue;
      RingTrace trace;
      trace.face = face;
      trace.year = value;
      trace.origin = TraceOrigin::Drawn;
      std::vector<glm::vec2> pts;
      for (const cv::Point& p : line)
        pts.push_back(imageToFaceMm(block, face, glm::vec2(p.x + 0.5f, p.y + 0.5f), size));
      trace.points = simplifyPolyline(pts, 0.5f * mmPerPx);
      out.push_back(std::move(trace));
    }
  }
  return out;
}

GrayImage8 ringImageFromTraces(const Annotations& annotations, FaceId face, const Block& block,
                               glm::ivec2 size) {
  cv::Mat m(size.y, size.x, CV_8UC1, cv::Scalar(255));
  constexpr int kShift = 4;  // sub-pixel vertices for cv::polylines
  for (const RingTrace& trace : annotations.traces) {
    if (trace.face != face || !trace.year || trace.points.empty()) continue;
    std::vector<cv::Point> pts;
    for (glm::vec2 q : trace.points) {
      const glm::vec2 p = faceMmToImage(block, face, q, size) - 0.5f;  // pixel index coordinates
      pts.emplace_back(static_cast<int>(std::lround(p.x * (1 << kShift))),
                       static_cast<int>(std::lround(p.y * (1 << kShift))));
    }
    // Pixel value = year, 255 = background: a year outside 0..254 cannot be written, and clamping it
    // silently (300 became 254) writes a wrong ring (issue 21).
    if (*trace.year < 0 || *trace.year > 254)
      throw InputError("the ring trace of year " + std::to_string(*trace.year) + " on face " +
                       std::string(1, faceLetter(face)) +
                       " does not fit a Mokume ring image (years 0 to 254); renumber the traces first");
    const int year = *trace.year;
    if (pts.size() == 1) pts.push_back(pts.front());
    cv::polylines(m, pts, false, cv::Scalar(year), 1, cv::LINE_8, kShift);
  }
  return fromMat(m);
}

std::vector<KnotMark> knotMarksFromImage(const GrayImage8& image, FaceId face, const Block& block) {
  std::vector<KnotMark> out;
  if (image.empty()) return out;
  const cv::Mat src = toMat(image);
  cv::Mat mask;
  cv::inRange(src, cv::Scalar(180), cv::Scalar(220), mask);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  for (int i = 1; i < n; ++i) {
    const glm::vec2 c(static_cast<float>(centroids.at<double>(i, 0)) + 0.5f,
                      static_cast<float>(centroids.at<double>(i, 1)) + 0.5f);
    out.push_back(
        {static_cast<int>(out.size()), face, imageToFaceMm(block, face, c, {image.width, image.height})});
  }
  return out;
}

GrayImage8 knotImageFromMarks(const Annotations& annotations, FaceId face, const Block& block,
                              glm::ivec2 size) {
  cv::Mat m(size.y, size.x, CV_8UC1, cv::Scalar(0));
  for (const KnotMark& mark : annotations.knots) {
    if (mark.face != face) continue;
    // Centred on the nearest whole pixel, so the disc is symmetric and its centroid is that pixel.
    const glm::vec2 p = faceMmToImage(block, face, mark.point, size) - 0.5f;
    cv::circle(m, cv::Point(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))), 2,
               cv::Scalar(200), cv::FILLED, cv::LINE_8);
  }
  return fromMat(m);
}

glm::ivec2 mokumeImageSize(const Block& block, FaceId face) {
  return block.faceImageSize(face, 256.0f / 40.0f);
}

}  // namespace kerf
