#pragma once
// How far a block's fitted knots and rings are from the log's truth, as issue 19's "Must show" asks
// (docs/knots.md, "A knot test bed cut from the spruce log"): the knot axis's angle and where it meets
// the marked faces, the knot's diameter there, and the rings on a hidden cut through the knot.
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "field/knot_field.hpp"
#include "fit/iso_contour_loss.hpp"
#include "log_cut_blocks.hpp"

namespace kerf::testing {

using ScalarField = std::function<float(const glm::vec3&)>;  // block mm -> time

inline double angleBetweenDeg(glm::vec3 a, glm::vec3 b) {
  const double c = std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

inline double medianOf(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Where a fitted knot's axis (a line) meets the plane of a face.
inline glm::vec3 axisOnFacePlane(const BlockKnot& knot, const Block& block, FaceId face) {
  const FaceFrame f = block.face(face);
  const glm::vec3 d = glm::normalize(knot.direction);
  return knot.origin + (glm::dot(f.center - knot.origin, f.normal) / glm::dot(d, f.normal)) * d;
}

// Twice the mean distance, over 72 directions in the plane through `centre` perpendicular to `axis`, from
// the axis to where `inside` turns false: the knot's diameter across its axis (block mm).
inline double crossSectionDiameter(const glm::vec3& centre, glm::vec3 axis,
                                   const std::function<bool(const glm::vec3&)>& inside, float maxMm = 40.0f) {
  axis = glm::normalize(axis);
  const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 e1 = glm::normalize(glm::cross(axis, helper)), e2 = glm::cross(axis, e1);
  double sum = 0;
  const int rays = 72;
  for (int i = 0; i < rays; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / rays;
    const glm::vec3 dir = std::cos(a) * e1 + std::sin(a) * e2;
    float lo = 0.0f, hi = maxMm;
    for (float r = 0.1f; r <= maxMm; r += 0.1f)
      if (!inside(centre + r * dir)) {
        lo = r - 0.1f, hi = r;
        break;
      }
    for (int j = 0; j < 20; ++j) (inside(centre + 0.5f * (lo + hi) * dir) ? lo : hi) = 0.5f * (lo + hi);
    sum += 0.5 * (lo + hi);
  }
  return 2.0 * sum / rays;
}

// The true knot's diameter where its centre line meets a face: the log model's own knot (its wood,
// T_b < t_s, field/knot_field.hpp Eq. 1 with the speed noise and, once dead, the frozen section of Eq. 5)
// cut perpendicular to the centre line.
inline double trueKnotDiameter(const KnotField& field, const Board& board, int k, const AxisCrossing& c) {
  const LogModel& log = field.log();
  const glm::vec3 tangentLog =
      knotAxisPoint(log, k, c.distance + 0.5f) - knotAxisPoint(log, k, c.distance - 0.5f);
  const int knots[] = {k};
  return crossSectionDiameter(c.point, glm::transpose(board.axes()) * tangentLog, [&](const glm::vec3& q) {
    const KnotFieldSample s = field.evaluate(board.toLog(q), knots);
    return s.knotTime < s.stemTime;
  });
}

// The fitted knot's diameter where its axis meets the face plane: the knot's wood, T_k < G
// (field/block_knots.hpp, Mokume Sec. 5.2.4 Eq. 7), cut perpendicular to its axis. A dead knot's wood is
// the section of its death (Eq. 5: T_k < min(G, death), its speed that of its death).
inline double fittedKnotDiameter(const GrowthField& stem, const BlockKnot& knot, const glm::vec3& onAxis,
                                 const KnotSettings& settings) {
  const glm::vec3 d = glm::normalize(knot.direction);
  return crossSectionDiameter(onAxis, d, [&](const glm::vec3& q) {
    const float g = std::min(stem.evaluate(q), knot.deathTime);
    const float v = knotSpeedAt(knot.speed, knot.taper, knot.taperAge, g, maxKnotSpeed(settings));
    return knotAxisDistance(&knot.origin.x, &d.x, q) / (v * stem.ringWidth()) < g;
  });
}

// A plane through the block that no face lies on: through `centre`, spanned by the unit vectors u, v.
struct HiddenCut {
  glm::vec3 centre{0.0f}, u{1, 0, 0}, v{0, 1, 0};
};

// The cut along a knot: through the middle of its centre line in the block, containing that line's chord
// and the block's y (up the log) made perpendicular to it, so it shows the knot lengthwise with the rings
// sweeping around it above and below.
inline HiddenCut cutAlongKnot(const AxisCrossing& entry, const AxisCrossing& exit) {
  HiddenCut cut;
  cut.centre = 0.5f * (entry.point + exit.point);
  cut.u = glm::normalize(exit.point - entry.point);
  cut.v = glm::normalize(glm::vec3(0, 1, 0) - glm::dot(glm::vec3(0, 1, 0), cut.u) * cut.u);
  return cut;
}

struct CutRingErrors {
  double medianMm = 0;      // over every point of the true iso-lines on the cut
  double medianNearMm = 0;  // over those `near` the knot
  int points = 0, nearPoints = 0;
};

// The rings on a hidden cut: the true field's iso-lines (levels every `levelSpacingMm` of its own mean
// spacing) traced on a grid of `stepMm`; at each of their points the fitted field's distance (mm, its
// value over its gradient) from its own iso-surface through the median of that line's fitted values.
// A constant shift of a whole ring (which ring is which year) is not an error; a ring bent elsewhere is.
inline CutRingErrors cutRingErrors(const ScalarField& truth, const ScalarField& fitted, const Block& block,
                                   const HiddenCut& cut, const std::function<bool(const glm::vec3&)>& near,
                                   float stepMm = 0.1f, float levelSpacingMm = 1.0f) {
  const float half = 0.5f * glm::length(block.size());
  const int n = static_cast<int>(std::ceil(2.0f * half / stepMm)) + 1;
  const auto at = [&](int i, int j) {
    return cut.centre + (-half + stepMm * static_cast<float>(i)) * cut.u +
           (-half + stepMm * static_cast<float>(j)) * cut.v;
  };
  std::vector<float> t(static_cast<std::size_t>(n) * n, std::nanf(""));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (const glm::vec3 p = at(i, j); block.contains(p)) t[static_cast<std::size_t>(j) * n + i] = truth(p);
  // The level spacing: the true field's median gradient along the grid times the spacing in mm.
  std::vector<double> gradients;
  float tMin = 1e30f, tMax = -1e30f;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const float a = t[static_cast<std::size_t>(j) * n + i], b = t[static_cast<std::size_t>(j) * n + i + 1],
                  c = t[static_cast<std::size_t>(j + 1) * n + i];
      if (std::isnan(a) || std::isnan(b) || std::isnan(c)) continue;
      gradients.push_back(std::hypot(b - a, c - a) / stepMm);
      tMin = std::min(tMin, a), tMax = std::max(tMax, a);
    }
  CutRingErrors out;
  if (gradients.empty()) return out;
  const double levelStep = levelSpacingMm * medianOf(gradients);
  struct Crossing {
    int level;
    double g, gradient;
    bool near;
  };
  std::vector<Crossing> crossings;
  const auto addCrossings = [&](int i0, int j0, int i1, int j1) {
    const float a = t[static_cast<std::size_t>(j0) * n + i0], b = t[static_cast<std::size_t>(j1) * n + i1];
    if (std::isnan(a) || std::isnan(b)) return;
    const int la = static_cast<int>(std::floor((std::min(a, b) - tMin) / levelStep)) + 1;
    const int lb = static_cast<int>(std::floor((std::max(a, b) - tMin) / levelStep));
    for (int l = la; l <= lb; ++l) {
      const double level = tMin + l * levelStep;
      const float f = static_cast<float>((level - a) / (b - a));
      const glm::vec3 p = at(i0, j0) + f * (at(i1, j1) - at(i0, j0));
      const float h = 0.05f;
      const glm::vec3 grad(fitted(p + glm::vec3(h, 0, 0)) - fitted(p - glm::vec3(h, 0, 0)),
                           fitted(p + glm::vec3(0, h, 0)) - fitted(p - glm::vec3(0, h, 0)),
                           fitted(p + glm::vec3(0, 0, h)) - fitted(p - glm::vec3(0, 0, h)));
      crossings.push_back({l, fitted(p), glm::length(grad) / (2.0 * h), near(p)});
    }
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n) addCrossings(i, j, i + 1, j);
      if (j + 1 < n) addCrossings(i, j, i, j + 1);
    }
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.level < b.level; });
  std::vector<double> all, nearOnes;
  for (std::size_t b = 0; b < crossings.size();) {
    std::size_t e = b;
    std::vector<double> g;
    while (e < crossings.size() && crossings[e].level == crossings[b].level) g.push_back(crossings[e++].g);
    if (g.size() >= 5) {
      const double median = medianOf(g);
      for (std::size_t i = b; i < e; ++i) {
        const double err = std::abs(crossings[i].g - median) / std::max(crossings[i].gradient, 1e-9);
        all.push_back(err);
        if (crossings[i].near) nearOnes.push_back(err);
      }
    }
    b = e;
  }
  out.points = static_cast<int>(all.size());
  out.nearPoints = static_cast<int>(nearOnes.size());
  out.medianMm = medianOf(all);
  out.medianNearMm = medianOf(nearOnes);
  return out;
}

// How far the points of each contour lie (mm, |f - the contour's median f| over |grad f|) from the
// iso-surface of `field` through their contour's median: 0 when every contour is an iso-line of `field`.
// With the true field, it measures the contours the fit was given (the ring detector's) against the truth.
inline CutRingErrors contourErrors(const ScalarField& field, const IsoContours& contours,
                                   const std::function<bool(const glm::vec3&)>& near) {
  std::vector<double> all, nearOnes;
  for (int c = 0; c < contours.count(); ++c) {
    std::vector<double> values;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
      values.push_back(field(contours.points[i]));
    const double median = medianOf(values);
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i) {
      const glm::vec3 p = contours.points[i];
      const float h = 0.05f;
      const glm::vec3 grad(field(p + glm::vec3(h, 0, 0)) - field(p - glm::vec3(h, 0, 0)),
                           field(p + glm::vec3(0, h, 0)) - field(p - glm::vec3(0, h, 0)),
                           field(p + glm::vec3(0, 0, h)) - field(p - glm::vec3(0, 0, h)));
      const double err = std::abs(values[i - contours.begin[c]] - median) /
                         std::max(static_cast<double>(glm::length(grad)) / (2.0 * h), 1e-9);
      all.push_back(err);
      if (near(p)) nearOnes.push_back(err);
    }
  }
  CutRingErrors out;
  out.points = static_cast<int>(all.size());
  out.nearPoints = static_cast<int>(nearOnes.size());
  out.medianMm = medianOf(all);
  out.medianNearMm = medianOf(nearOnes);
  return out;
}

// The distance from p to a polyline.
inline float distanceToPolyline(const glm::vec3& p, const std::vector<glm::vec3>& line) {
  float best = 1e30f;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const glm::vec3 a = line[i], ab = line[i + 1] - a;
    const float s = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
    best = std::min(best, glm::length(p - (a + s * ab)));
  }
  return best;
}

// The true centre line of knot k between two distances, in the block frame, every half millimetre.
inline std::vector<glm::vec3> trueAxisInBlock(const LogModel& log, int k, const Board& board, float d0,
                                              float d1) {
  std::vector<glm::vec3> line;
  for (float d = d0; d < d1; d += 0.5f) line.push_back(logToBlock(board, knotAxisPoint(log, k, d)));
  line.push_back(logToBlock(board, knotAxisPoint(log, k, d1)));
  return line;
}

}  // namespace kerf::testing
