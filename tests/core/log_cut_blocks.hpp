#pragma once
// Blocks cut from a log around its real knots, for the knot test bed (issue 19 item 3, docs/knots.md
// "A knot test bed cut from the spruce log"): which knots, by fixed rules on the log's own data; where the
// block sits (a Board of render/board_renderer.hpp); the true knot axis and where it meets the faces.
//
// The knot's centre line is the log model's skeleton (Larsson et al. 2022 Sec. 4.4.2, Table 2): at the
// distance d from the pith it passes through pith(z(d)) + d (cos omega(d), sin omega(d)) at height z(d),
// the point field/knot_field.cpp takes as the knot's pseudo-nearest skeleton point (Eq. 1).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "field/log_model.hpp"
#include "render/board_renderer.hpp"
#include "rings/annotations.hpp"

namespace kerf::testing {

// Where the bed cuts its blocks: centred on the knot axis this far from the pith (mm). The blocks then
// span about 35-85 mm from the pith (Mokume's cubes lie 15-330 mm from theirs) and stay inside the
// thinnest part of the stem (104 mm).
inline constexpr float kBedDistanceMm = 60.0f;

// A point of knot k's centre line, log frame.
inline glm::vec3 knotAxisPoint(const LogModel& log, int k, float d) {
  const Knot& knot = log.knots[k];
  const float z = knot.heightAt(d), w = knot.azimuthAt(d);
  const glm::vec2 p = log.stem.pithAt(z) + d * glm::vec2(std::cos(w), std::sin(w));
  return {p.x, p.y, z};
}

// The rise of knot k at distance d: the angle of its centre line above the horizontal (degrees).
inline float knotRiseDeg(const LogModel& log, int k, float d) {
  const glm::vec3 a = knotAxisPoint(log, k, d - 1.0f), b = knotAxisPoint(log, k, d + 1.0f);
  const glm::vec3 t = glm::normalize(b - a);
  return std::asin(std::clamp(t.z, -1.0f, 1.0f)) * 180.0f / std::numbers::pi_v<float>;
}

// The least distance between the centre lines of knots a and b over [d0, d1] (at equal distances from
// the pith: both radiate from the pith, so their nearest points lie at about the same distance).
inline float knotSeparation(const LogModel& log, int a, int b, float d0, float d1) {
  float best = std::numeric_limits<float>::infinity();
  for (float d = d0; d <= d1; d += 2.0f)
    best = std::min(best, glm::length(knotAxisPoint(log, a, d) - knotAxisPoint(log, b, d)));
  return best;
}

// How far knot k stays from every knot but those in `besides`, over the block's distances.
inline float knotIsolation(const LogModel& log, int k, const std::vector<int>& besides = {}) {
  float best = std::numeric_limits<float>::infinity();
  for (int j = 0; j < static_cast<int>(log.knots.size()); ++j) {
    if (j == k || std::find(besides.begin(), besides.end(), j) != besides.end()) continue;
    best = std::min(best, knotSeparation(log, k, j, kBedDistanceMm - 40.0f, kBedDistanceMm + 40.0f));
  }
  return best;
}

// One block of the bed: its knots (log indices), its size and how it is turned away from facing the pith.
struct BedBlockSpec {
  std::string name;              // what it tests, e.g. "live", "dead", "two knots"
  std::vector<int> knots;        // the knots it is cut around (marked and compared)
  float sizeMm = 50.0f;          // a cube
  float turnAboutLogDeg = 0.0f;  // about the log's axis (the knot then meets face A obliquely)
  float tiltDeg = 0.0f;          // about the block's width axis (the pith then leans in the block)
};

// The block placed in the log: centred on its knots' axes at kBedDistanceMm, face A looking at the pith
// (as render/board_renderer.hpp's flat-sawn boards), then turned by the spec's angles. Block y runs up
// the log, the principal pith direction of Kerf's fit.
inline Board placeBedBlock(const LogModel& log, const BedBlockSpec& spec) {
  glm::vec3 centre(0.0f);
  for (int k : spec.knots) centre += knotAxisPoint(log, k, kBedDistanceMm);
  centre /= static_cast<float>(spec.knots.size());
  const glm::vec2 out = glm::vec2(centre) - log.stem.pithAt(centre.z);
  const float azimuthDeg = std::atan2(out.y, out.x) * 180.0f / std::numbers::pi_v<float>;
  Board b;
  b.center = centre;
  b.size = glm::vec3(spec.sizeMm);
  b.rotationDeg = glm::vec3(spec.tiltDeg, azimuthDeg - 90.0f + spec.turnAboutLogDeg, 0.0f);
  return b;
}

// A log-frame point in the board's block frame (mm).
inline glm::vec3 logToBlock(const Board& board, const glm::vec3& p) {
  return glm::transpose(board.axes()) * (p - board.center);
}

// Where a knot's centre line meets a face of the block: block mm, the face, the distance from the pith.
struct AxisCrossing {
  FaceId face = FaceId::A;
  glm::vec3 point{0.0f};  // block mm
  float distance = 0;     // d along the knot
};

// The face whose plane a point on the block's surface lies on.
inline FaceId faceAt(const Block& block, const glm::vec3& q) {
  const glm::vec3 r = glm::abs(q) / block.halfSize();
  if (r.x >= r.y && r.x >= r.z) return q.x > 0 ? FaceId::E : FaceId::C;
  if (r.y >= r.z) return q.y > 0 ? FaceId::B : FaceId::D;
  return q.z > 0 ? FaceId::A : FaceId::F;
}

// Where knot k's centre line enters and leaves the board (in order of d); empty when it misses.
inline std::vector<AxisCrossing> axisCrossings(const LogModel& log, int k, const Board& board) {
  const Block block = board.block();
  const glm::vec3 h = block.halfSize();
  const auto inside = [&](float d) {
    const glm::vec3 q = logToBlock(board, knotAxisPoint(log, k, d));
    return std::abs(q.x) <= h.x && std::abs(q.y) <= h.y && std::abs(q.z) <= h.z;
  };
  std::vector<AxisCrossing> out;
  const float step = 0.25f, dMax = log.stem.maxRadius();
  bool was = inside(0.0f);
  for (float d = step; d <= dMax; d += step) {
    const bool is = inside(d);
    if (is == was) continue;
    float lo = d - step, hi = d;  // bisect the change to well under a micrometre
    for (int i = 0; i < 30; ++i) (inside(0.5f * (lo + hi)) == was ? lo : hi) = 0.5f * (lo + hi);
    AxisCrossing c;
    c.distance = 0.5f * (lo + hi);
    c.point = logToBlock(board, knotAxisPoint(log, k, c.distance));
    c.face = faceAt(block, c.point);
    out.push_back(c);
    was = is;
  }
  return out;
}

// The marks a user would set: knot id k at each point where its centre line meets a face.
inline std::vector<KnotMark> knotMarksAtCrossings(const LogModel& log, int k, const Board& board) {
  std::vector<KnotMark> marks;
  for (const AxisCrossing& c : axisCrossings(log, k, board))
    marks.push_back({k, c.face, blockToFaceMm(board.block(), c.face, c.point)});
  return marks;
}

// The bed's blocks, picked by rules on the log's data alone (never on fit results). Candidates start
// 0.3 m from either end of the log and meet the block's faces twice.
//  - live: alive through the block (death at least 40 mm beyond its centre), the most isolated;
//  - dead: dies in the inner half of its block, the most isolated; the block turned 25 deg about the log;
//  - steep: alive through the block, the steepest rise among knots 40 mm from any other; turned 40 deg
//    about the log and tilted 12 deg, so the knot meets the faces at a slant;
//  - two knots: the closest pair at least 15 mm apart (separable) whose other neighbours stay 30 mm off,
//    in a 60 mm block.
inline std::vector<BedBlockSpec> pickBedBlocks(const LogModel& log) {
  const int n = static_cast<int>(log.knots.size());
  const float d = kBedDistanceMm;
  const auto inLog = [&](int k) {
    const float z = log.knots[k].heightAt(d);
    return z > 300.0f && z < log.stem.height() - 300.0f;
  };
  const auto crossesTwice = [&](const BedBlockSpec& s) {
    const Board b = placeBedBlock(log, s);
    for (int k : s.knots)
      if (axisCrossings(log, k, b).size() != 2) return false;
    return true;
  };
  std::vector<BedBlockSpec> out;
  const auto best = [&](const std::string& name, auto accept, auto score, float turn, float tilt) {
    int pick = -1;
    float pickScore = -std::numeric_limits<float>::infinity();
    for (int k = 0; k < n; ++k) {
      if (!inLog(k) || !accept(k)) continue;
      BedBlockSpec s{name, {k}, 50.0f, turn, tilt};
      if (!crossesTwice(s)) continue;
      const float v = score(k);
      if (v > pickScore) pickScore = v, pick = k;
    }
    if (pick >= 0) out.push_back({name, {pick}, 50.0f, turn, tilt});
  };
  const auto isolation = [&](int k) { return knotIsolation(log, k); };
  best(
      "live", [&](int k) { return log.knots[k].deathDistance >= d + 40.0f; }, isolation, 0.0f, 0.0f);
  best(
      "dead",
      [&](int k) { return log.knots[k].deathDistance >= d - 25.0f && log.knots[k].deathDistance < d; },
      isolation, 25.0f, 0.0f);
  best(
      "steep",
      [&](int k) { return log.knots[k].deathDistance >= d + 40.0f && knotIsolation(log, k) >= 40.0f; },
      [&](int k) { return knotRiseDeg(log, k, d); }, 40.0f, 12.0f);
  // Two knots in one block.
  float pairBest = std::numeric_limits<float>::infinity();
  BedBlockSpec pair{"two knots", {}, 60.0f, 0.0f, 0.0f};
  for (int a = 0; a < n; ++a) {
    if (!inLog(a)) continue;
    for (int b = a + 1; b < n; ++b) {
      if (!inLog(b)) continue;
      const float sep = knotSeparation(log, a, b, d - 20.0f, d + 20.0f);
      if (sep < 15.0f || sep >= pairBest) continue;
      if (knotIsolation(log, a, {b}) < 30.0f || knotIsolation(log, b, {a}) < 30.0f) continue;
      const BedBlockSpec s{"two knots", {a, b}, 60.0f, 0.0f, 0.0f};
      if (!crossesTwice(s)) continue;
      pairBest = sep, pair = s;
    }
  }
  if (!pair.knots.empty()) out.push_back(pair);
  return out;
}

// The log with the given knots alive to the bark (their deaths removed): the bed's "without death" case.
inline LogModel withoutDeaths(LogModel log, const std::vector<int>& knots) {
  for (int k : knots) log.knots[k].deathDistance = std::numeric_limits<float>::infinity();
  return log;
}

}  // namespace kerf::testing
