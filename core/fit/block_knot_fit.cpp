#include "fit/block_knot_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <set>

#include "fit/ceres_progress.hpp"
#include "fit/pith_fit.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace {

constexpr float kMinSpeed = 0.02f;
constexpr double kAliveDeath = 1e30;      // the death parameter of an alive knot (held)
constexpr double kMinDeath = 1.0;         // years: a branch lives a year at least
constexpr int kFarPointsPerContour = 16;  // anchor each contour's level away from the knot

// A knot's fixed frame for the angle beta of a dead knot's butterfly (knotAngleOf), from its initial axis.
struct KnotFrame {
  glm::vec3 up{0, 0, 1}, side{1, 0, 0};
};

// G_k of one knot at p (Eq. 7 and Eq. 6) from the stem time and radius, for the residuals below.
// Parameter blocks per knot: `knot` = origin (3), direction (3), log speed; `taper` = BlockKnot::taper,
// with the knot's taper age fixed; `death` = BlockKnot::deathTime (years; 1e30 and held: alive).
template <typename T>
T mergedNearKnot(const glm::vec3& p, const T& stem, const T& radius, const T* knot, const T* taper,
                 const T* death, const T& kStem, float ringWidth, float taperAge, const KnotFrame& frame,
                 const KnotSettings& settings) {
  using std::exp;
  using std::sqrt;
  const T norm = sqrt(knot[3] * knot[3] + knot[4] * knot[4] + knot[5] * knot[5]);
  const T direction[3] = {knot[3] / norm, knot[4] / norm, knot[5] / norm};
  const T distance = knotAxisDistance(knot, direction, p);
  const T growing = stem < death[0] ? stem : death[0];  // a dead knot keeps the speed of its death
  const T speed = taperedKnotSpeed(exp(knot[6]), taper[0], taperAge, growing, maxKnotSpeed(settings));
  KnotDeathAt<T> dead{death[0], T(0)};
  if (death[0] < stem) {
    const T rel[3] = {T(p.x) - knot[0], T(p.y) - knot[1], T(p.z) - knot[2]};
    dead.beta = knotAngleOf(rel, direction, frame.up, frame.side);
  }
  const KnotTerm<T> term = knotTerm(stem, distance, radius, speed, ringWidth, kStem, settings, dead);
  if (!(term.window > T(0))) return stem;
  return (term.time < stem ? term.time : stem) + term.smoothing;
}

// One contour point near a knot: its G_k (one knot merged into the fixed stem time) against its
// contour's free level.
struct NearPointResidual {
  glm::vec3 p;
  double stemTime;
  float stemRadius, ringWidth, taperAge;
  KnotFrame frame;
  const KnotSettings* settings;

  template <typename T>
  bool operator()(const T* knot, const T* taper, const T* death, const T* kStem, const T* level,
                  T* residual) const {
    residual[0] = mergedNearKnot(p, T(stemTime), T(stemRadius), knot, taper, death, kStem[0], ringWidth,
                                 taperAge, frame, *settings) -
                  level[0];
    return true;
  }
};

// A contour point the knots do not reach: only its level is free.
struct FarPointResidual {
  double stemTime;
  template <typename T>
  bool operator()(const T* level, T* residual) const {
    residual[0] = T(stemTime) - level[0];
    return true;
  }
};

// The undeformed stem of a free pith axis (origin 3, direction 3): G = distance / ring width.
template <typename T>
void undeformedStem(const T* pith, const glm::vec3& p, float ringWidth, T& time, T& radius) {
  using std::sqrt;
  const T norm = sqrt(pith[3] * pith[3] + pith[4] * pith[4] + pith[5] * pith[5]);
  const T v[3] = {pith[3] / norm, pith[4] / norm, pith[5] / norm};
  const T rel[3] = {T(p.x) - pith[0], T(p.y) - pith[1], T(p.z) - pith[2]};
  const T h = rel[0] * v[0] + rel[1] * v[1] + rel[2] * v[2];
  const T d[3] = {rel[0] - h * v[0], rel[1] - h * v[1], rel[2] - h * v[2]};
  radius = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + T(1e-12));
  time = radius / T(ringWidth);
}

struct JointNearResidual {
  glm::vec3 p;
  float ringWidth, taperAge;
  KnotFrame frame;
  const KnotSettings* settings;

  template <typename T>
  bool operator()(const T* pith, const T* knot, const T* taper, const T* death, const T* kStem,
                  const T* level, T* residual) const {
    T stem, radius;
    undeformedStem(pith, p, ringWidth, stem, radius);
    residual[0] =
        mergedNearKnot(p, stem, radius, knot, taper, death, kStem[0], ringWidth, taperAge, frame, *settings) -
        level[0];
    return true;
  }
};

struct JointFarResidual {
  glm::vec3 p;
  float ringWidth;
  template <typename T>
  bool operator()(const T* pith, const T* level, T* residual) const {
    T stem, radius;
    undeformedStem(pith, p, ringWidth, stem, radius);
    residual[0] = stem - level[0];
    return true;
  }
};

// Keeps the knot's direction vector at unit length and its origin from sliding along the axis
// unconstrained (moving it along the axis outside the block changes nothing: a gauge freedom).
// Issue 19 item 1: a mark the user placed holds the knot's axis within its accuracy. Inside 90 % of the
// accuracy the mark costs next to nothing, so there the contours place the axis; beyond, the cost rises so
// steeply (weighted by sqrt(the knot's contour points), each of whose soft-L1 costs stays far below 1)
// that no gain on the contours can carry the axis past the accuracy.
struct MarkResidual {
  glm::vec3 mark, faceNormal;  // the distance is taken on the face's plane (knotAxisMarkDistance)
  double freeMm;               // 0.9 x the mark's accuracy
  double weight;               // 10 sqrt(near points) / accuracy, per mm beyond freeMm
  template <typename T>
  bool operator()(const T* knot, T* residual) const {
    using std::sqrt;
    const T norm = sqrt(knot[3] * knot[3] + knot[4] * knot[4] + knot[5] * knot[5]);
    const T direction[3] = {knot[3] / norm, knot[4] / norm, knot[5] / norm};
    // A hinge with a rounded knee (quadratic over the first 10 % of the free distance): exactly zero
    // inside, and Levenberg-Marquardt does not crawl along its corner as it did along a sharp one.
    const T beyond = knotAxisMarkDistance(knot, direction, mark, faceNormal) - T(freeMm);
    const T knee(0.1 * freeMm);
    residual[0] = beyond <= T(0)  ? T(0)
                  : beyond < knee ? T(weight) * beyond * beyond / (T(2) * knee)
                                  : T(weight) * (beyond - T(0.5) * knee);
    return true;
  }
};

// Issue 19 item 2: a point of the knot's edge seen on a photo (rings/knot_outline.hpp) lies on the knot's
// surface, where its own time equals the stem's (T_k = d_k / (v w) = G: Eq. 7's two arguments equal). In
// the stem's ring spacings, as the contours' residuals: (d_k - v_k(G) w G) / w. A dead knot's surface
// stays where it was at its death (Eq. 5): G is then the death time.
struct EdgeGeometry {
  glm::vec3 p;
  float ringWidth, taperAge, maxSpeed;
  template <typename T>
  T gap(const T* knot, const T* taper, const T* death, const T& stemTime) const {
    using std::exp;
    using std::sqrt;
    const T norm = sqrt(knot[3] * knot[3] + knot[4] * knot[4] + knot[5] * knot[5]);
    const T direction[3] = {knot[3] / norm, knot[4] / norm, knot[5] / norm};
    const T grown = stemTime < death[0] ? stemTime : death[0];
    const T speed = taperedKnotSpeed(exp(knot[6]), taper[0], taperAge, grown, maxSpeed);
    return knotAxisDistance(knot, direction, p) / T(ringWidth) - speed * grown;
  }
};

struct KnotEdgeResidual {
  EdgeGeometry edge;
  double stemTime;  // G at p, fixed
  template <typename T>
  bool operator()(const T* knot, const T* taper, const T* death, T* residual) const {
    residual[0] = edge.gap(knot, taper, death, T(stemTime));
    return true;
  }
};

struct JointKnotEdgeResidual {
  EdgeGeometry edge;
  template <typename T>
  bool operator()(const T* pith, const T* knot, const T* taper, const T* death, T* residual) const {
    T stem, radius;
    undeformedStem(pith, edge.p, edge.ringWidth, stem, radius);
    residual[0] = edge.gap(knot, taper, death, stem);
    return true;
  }
};

struct KnotGauge {
  glm::dvec3 origin0;
  template <typename T>
  bool operator()(const T* knot, T* residual) const {
    residual[0] = knot[3] * knot[3] + knot[4] * knot[4] + knot[5] * knot[5] - T(1);
    for (int i = 0; i < 3; ++i) residual[1 + i] = T(0.01) * (knot[i] - T(origin0[i]));
    return true;
  }
};

double angleDeg(glm::vec3 a, glm::vec3 b) {
  const double c = std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

}  // namespace

InitialKnot initialKnotFromMarks(const std::vector<KnotMark>& marks, const Block& block, const PithAxis& pith,
                                 float speed) {
  InitialKnot out;
  if (marks.empty()) {
    out.note = "no marks";
    return out;
  }
  BlockKnot knot;
  knot.id = marks.front().knot;
  knot.speed = speed;
  const glm::vec3 first = faceMmToBlock(block, marks[0].face, marks[0].point);
  if (marks.size() == 1) {
    // A knot seen on one face: a branch grows out of the pith, so start on the pith axis and run
    // perpendicular to it through the mark.
    const glm::vec3 onPith = pith.origin + glm::dot(first - pith.origin, pith.direction) * pith.direction;
    if (glm::length(first - onPith) < 1.0f) {
      out.note = "its only mark lies on the pith axis: no direction for the knot";
      return out;
    }
    knot.origin = onPith;
    knot.direction = glm::normalize(first - onPith);
    out.note = "one mark: axis from the pith perpendicular through the mark";
    out.knot = knot;
    return out;
  }
  const glm::vec3 second = faceMmToBlock(block, marks[1].face, marks[1].point);
  if (glm::length(second - first) < 1.0f) {
    out.note = "its two marks are less than 1 mm apart: no direction for the knot";
    return out;
  }
  // Where the line through the marks passes closest to the pith axis: the knot starts there.
  glm::vec3 d = glm::normalize(second - first);
  const glm::vec3 w0 = first - pith.origin;
  const float b = glm::dot(d, pith.direction);
  const float den = 1.0f - b * b;
  if (den < 1e-3f) {
    out.note = "its marks line up with the pith axis: a knot cannot run along the pith";
    return out;
  }
  const float t = (b * glm::dot(pith.direction, w0) - glm::dot(d, w0)) / den;
  knot.origin = first + t * d;
  const glm::vec3 middle = 0.5f * (first + second);
  if (glm::dot(middle - knot.origin, d) < 0.0f) d = -d;  // from the pith outward
  knot.direction = d;
  out.note = "axis through the two marks, starting where it passes the pith";
  if (glm::dot(first - knot.origin, d) < 0.0f || glm::dot(second - knot.origin, d) < 0.0f)
    out.note += " (the pith passes between the marks: only the outer part is a knot)";
  if (marks.size() > 2) out.note += " (" + std::to_string(marks.size()) + " marks: the first two used)";
  out.knot = knot;
  return out;
}

double nearKnotLoss(const IsoContours& contours, const std::vector<double>& values,
                    const std::vector<bool>& near) {
  double sum = 0;
  int n = 0;
  for (int c = 0; c < contours.count(); ++c) {
    bool any = false;
    for (int i = contours.begin[c]; i < contours.begin[c + 1] && !any; ++i) any = near[i];
    if (!any) continue;
    std::vector<double> v(values.begin() + contours.begin[c], values.begin() + contours.begin[c + 1]);
    const double median = lowerMedian(v);
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
      if (near[i]) sum += std::abs(values[i] - median), ++n;
  }
  return n > 0 ? sum / n : 0.0;
}

IsoContours contoursAwayFromKnots(const IsoContours& contours, const GrowthField& stem,
                                  const BlockKnots& knots, double years, int minPoints) {
  IsoContours out;
  const PithAxis& pith = stem.axis();
  for (int c = 0; c < contours.count(); ++c) {
    std::vector<glm::vec3> kept;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i) {
      const glm::vec3 p = contours.points[i];
      const Cylindrical cyl = pith.toCylindrical(p);
      const float g = stem.evaluate(cyl);
      if (std::abs(knots.merge(p, g, cyl.radius).time - g) <= years) kept.push_back(p);
    }
    if (static_cast<int>(kept.size()) < minPoints) continue;
    out.points.insert(out.points.end(), kept.begin(), kept.end());
    out.begin.push_back(static_cast<int>(out.points.size()));
    out.face.push_back(contours.face[c]);
    out.year.push_back(contours.year[c]);
  }
  return out;
}

namespace {

// fitBlockKnots, and with freePith the pith axis of an undeformed `stem` too (fitPithAndKnots).
BlockKnotFitResult fitKnots(const IsoContours& contours, const Block& block, const GrowthField& stem,
                            const std::vector<KnotMark>& marks, const KnotSettings& settings,
                            const BlockKnotFitOptions& options, const Progress& progress, bool freePith,
                            std::array<double, 6>* pithOut) {
  const Stopwatch clock;
  BlockKnotFitResult out;
  out.kStem = settings.knotSmoothStem;
  const PithAxis& pith = stem.axis();
  const float maxSpeed = 0.9f * std::min(settings.knotReachStart, settings.knotReachEnd);
  const float speed0 = std::clamp(settings.knotSpeed, kMinSpeed, maxSpeed);

  std::map<int, std::vector<KnotMark>> byId;
  for (const KnotMark& m : marks) byId[m.knot].push_back(m);
  std::vector<BlockKnot> initial;
  std::vector<int> entryOf;  // entry index of each initial knot
  for (const auto& [id, knotMarks] : byId) {
    BlockKnotFitEntry e;
    e.id = id;
    e.marks = static_cast<int>(knotMarks.size());
    for (const KnotMark& m : knotMarks) e.faces.push_back(m.face);
    InitialKnot init = initialKnotFromMarks(knotMarks, block, pith, speed0);
    for (const BlockKnot& start : options.start)
      if (start.id == id) {
        init.knot = start;
        init.knot->speed = std::clamp(start.speed, kMinSpeed, maxSpeed);
        init.note += "; refined from its fit on the undeformed field";
      }
    e.note = init.note;
    if (init.knot) {
      e.kept = true;
      e.initial = e.fitted = *init.knot;
      initial.push_back(*init.knot);
      entryOf.push_back(static_cast<int>(out.entries.size()));
    }
    out.entries.push_back(e);
  }
  if (initial.empty()) {
    out.seconds = clock.seconds();
    return out;
  }

  // The fixed stem field at every contour point, and the knot each point is near (-1: none).
  const int n = static_cast<int>(contours.points.size());
  std::vector<double> stemTime(n);
  std::vector<float> stemRadius(n);
  std::vector<int> nearKnot(n, -1);
  for (int i = 0; i < n; ++i) {
    const glm::vec3 p = contours.points[i];
    const Cylindrical c = pith.toCylindrical(p);
    stemTime[i] = stem.evaluate(c);
    stemRadius[i] = c.radius;
    for (int k = 0; k < static_cast<int>(initial.size()) && nearKnot[i] < 0; ++k) {
      const float d = knotAxisDistance(&initial[k].origin.x, &initial[k].direction.x, p);
      if (d < options.nearReach * settings.knotReachEnd * c.radius) nearKnot[i] = k;
    }
  }
  std::vector<int> nearCount(initial.size(), 0);
  for (int k : nearKnot)
    if (k >= 0) ++nearCount[k];
  // Every stride-th near point of a knot is fitted (options.maxNearPoints); `fittedNear` counts them.
  std::vector<int> stride(initial.size(), 1), seen(initial.size(), 0), fittedNear(initial.size(), 0);
  if (options.maxNearPoints > 0)
    for (std::size_t k = 0; k < initial.size(); ++k)
      stride[k] = std::max(1, (nearCount[k] + options.maxNearPoints - 1) / options.maxNearPoints);

  // The knots' edges on the photos (options.outlines), lifted onto their faces. A knot seen on two faces
  // or more has its taper fitted too (its diameter at two distances from the pith); its taper age, where
  // its speed holds, is then the median stem time of its edges (a cone stays the same cone).
  std::vector<std::vector<glm::vec3>> edges(initial.size());
  std::vector<bool> taperFree(initial.size(), false);
  for (std::size_t k = 0; k < initial.size(); ++k) {
    BlockKnotFitEntry& e = out.entries[entryOf[k]];
    for (const KnotOutline& o : options.outlines) {
      if (o.knot != e.id || !o.found || o.edge.empty()) continue;
      ++e.outlines;
      for (glm::vec2 q : o.edge) edges[k].push_back(faceMmToBlock(block, o.face, q));
    }
    e.edgePoints = static_cast<int>(edges[k].size());
    taperFree[k] = e.outlines >= 2;
    if (edges[k].empty() || initial[k].taper != 0.0f) continue;
    std::vector<double> ages;
    for (const glm::vec3& p : edges[k]) ages.push_back(stem.evaluate(pith.toCylindrical(p)));
    initial[k].taperAge = std::max(0.1f, static_cast<float>(lowerMedian(ages)));
  }

  // Parameters: per knot origin (3), direction (3), log speed, its taper and its death; the shared k_stem;
  // a level per contour. A dead knot (from `start`: the joint stage found it stopped thickening, below)
  // has its death fitted and no taper; an alive one its taper and no death.
  std::vector<double> taperParams(initial.size()), deathParams(initial.size());
  std::vector<KnotFrame> frames(initial.size());
  for (std::size_t k = 0; k < initial.size(); ++k) {
    taperParams[k] = initial[k].taper;
    deathParams[k] = initial[k].dead() ? initial[k].deathTime : kAliveDeath;
    knotFrame(initial[k].direction, pith.direction, frames[k].up, frames[k].side);
  }
  std::vector<std::array<double, 7>> knotParams(initial.size());
  for (std::size_t k = 0; k < initial.size(); ++k) {
    const BlockKnot& b = initial[k];
    knotParams[k] = {b.origin.x,
                     b.origin.y,
                     b.origin.z,
                     b.direction.x,
                     b.direction.y,
                     b.direction.z,
                     std::log(static_cast<double>(b.speed))};
  }
  double kStem = settings.knotSmoothStem;
  const BlockKnots initialKnots(initial, settings, stem.ringWidth(), pith.direction);
  std::vector<double> levels(contours.count(), 0.0);
  ceres::Problem problem;
  std::vector<bool> knotInProblem(initial.size(), false);
  std::array<double, 6> pithParams = {pith.origin.x,    pith.origin.y,    pith.origin.z,
                                      pith.direction.x, pith.direction.y, pith.direction.z};
  const float ringWidth = stem.ringWidth();
  for (int c = 0; c < contours.count(); ++c) {
    std::vector<int> near, far;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
      (nearKnot[i] >= 0 && nearCount[nearKnot[i]] >= options.minNearPoints ? near : far).push_back(i);
    if (near.empty()) continue;
    std::vector<double> merged;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
      merged.push_back(
          initialKnots.merge(contours.points[i], static_cast<float>(stemTime[i]), stemRadius[i]).time);
    levels[c] = lowerMedian(merged);
    for (int i : near) {
      const int k = nearKnot[i];
      if (seen[k]++ % stride[k] != 0) continue;
      ++fittedNear[k];
      if (freePith) {
        auto* cost = new ceres::AutoDiffCostFunction<JointNearResidual, 1, 6, 7, 1, 1, 1, 1>(
            new JointNearResidual{contours.points[i], ringWidth, initial[k].taperAge, frames[k], &settings});
        problem.AddResidualBlock(cost, new ceres::SoftLOneLoss(0.1), pithParams.data(), knotParams[k].data(),
                                 &taperParams[k], &deathParams[k], &kStem, &levels[c]);
      } else {
        auto* cost = new ceres::AutoDiffCostFunction<NearPointResidual, 1, 7, 1, 1, 1, 1>(
            new NearPointResidual{contours.points[i], stemTime[i], stemRadius[i], ringWidth,
                                  initial[k].taperAge, frames[k], &settings});
        problem.AddResidualBlock(cost, new ceres::SoftLOneLoss(0.1), knotParams[k].data(), &taperParams[k],
                                 &deathParams[k], &kStem, &levels[c]);
      }
      knotInProblem[k] = true;
    }
    // Away from the knots: a few points anchor the level; with a free pith, all of them (every 4th) hold it.
    const int per =
        freePith ? std::max(kFarPointsPerContour, static_cast<int>(far.size()) / 4) : kFarPointsPerContour;
    const int step = std::max(1, static_cast<int>(far.size()) / per);
    for (std::size_t j = 0; j < far.size(); j += step) {
      if (freePith) {
        auto* cost = new ceres::AutoDiffCostFunction<JointFarResidual, 1, 6, 1>(
            new JointFarResidual{contours.points[far[j]], ringWidth});
        problem.AddResidualBlock(cost, new ceres::SoftLOneLoss(0.1), pithParams.data(), &levels[c]);
      } else {
        auto* cost =
            new ceres::AutoDiffCostFunction<FarPointResidual, 1, 1>(new FarPointResidual{stemTime[far[j]]});
        problem.AddResidualBlock(cost, new ceres::SoftLOneLoss(0.1), &levels[c]);
      }
    }
  }
  // The edges' residuals: together as heavy as the knot's contour points.
  for (std::size_t k = 0; k < initial.size(); ++k) {
    const BlockKnotFitEntry& e = out.entries[entryOf[k]];
    if (edges[k].empty()) continue;
    // The weight scales the robust loss, not the residual: the loss still turns from squares to absolute
    // values at 0.1 ring spacings (a pixel or two), as the contours' does.
    const double weight = std::max(
        1.0, static_cast<double>(std::max(fittedNear[k], e.edgePoints)) / static_cast<double>(e.edgePoints));
    const auto edgeLoss = [weight] {
      return new ceres::ScaledLoss(new ceres::SoftLOneLoss(0.1), weight, ceres::TAKE_OWNERSHIP);
    };
    for (const glm::vec3& p : edges[k]) {
      const EdgeGeometry edge{p, ringWidth, initial[k].taperAge, maxKnotSpeed(settings)};
      if (freePith) {
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<JointKnotEdgeResidual, 1, 6, 7, 1, 1>(
                                     new JointKnotEdgeResidual{edge}),
                                 edgeLoss(), pithParams.data(), knotParams[k].data(), &taperParams[k],
                                 &deathParams[k]);
      } else {
        const double g = stem.evaluate(pith.toCylindrical(p));
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<KnotEdgeResidual, 1, 7, 1, 1>(new KnotEdgeResidual{edge, g}),
            edgeLoss(), knotParams[k].data(), &taperParams[k], &deathParams[k]);
      }
    }
    knotInProblem[k] = true;
  }
  for (std::size_t k = 0; k < initial.size(); ++k) {
    BlockKnotFitEntry& e = out.entries[entryOf[k]];
    e.nearPoints = nearCount[k];
    if (!knotInProblem[k]) {
      e.note +=
          "; too few contour points near it (" + std::to_string(nearCount[k]) + "): kept at its initial axis";
      continue;
    }
    const glm::dvec3 origin0(knotParams[k][0], knotParams[k][1], knotParams[k][2]);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<KnotGauge, 4, 7>(new KnotGauge{origin0}),
                             nullptr, knotParams[k].data());
    for (const KnotMark& m : byId[e.id]) {
      if (m.released) continue;
      const double accuracy = std::max(0.05f, m.accuracyMm);
      const double weight = 10.0 * std::sqrt(std::max(1, fittedNear[k])) / accuracy;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<MarkResidual, 1, 7>(new MarkResidual{
              faceMmToBlock(block, m.face, m.point), block.face(m.face).normal, 0.9 * accuracy, weight}),
          nullptr, knotParams[k].data());
    }
    problem.SetParameterLowerBound(knotParams[k].data(), 6, std::log(kMinSpeed));
    problem.SetParameterUpperBound(knotParams[k].data(), 6, std::log(maxSpeed));
    if (initial[k].dead()) {
      // Where it died: between a year and three times where the joint stage put it.
      problem.SetParameterBlockConstant(&taperParams[k]);
      problem.SetParameterLowerBound(&deathParams[k], 0, kMinDeath);
      problem.SetParameterUpperBound(&deathParams[k], 0, std::max(3.0 * deathParams[k], kMinDeath + 1.0));
    } else if (taperFree[k]) {
      problem.SetParameterLowerBound(&taperParams[k], 0, -kMaxKnotTaper);
      problem.SetParameterUpperBound(&taperParams[k], 0, kMaxKnotTaper);
    } else {
      problem.SetParameterBlockConstant(&taperParams[k]);  // one face's edge: no second diameter
    }
    if (!initial[k].dead()) problem.SetParameterBlockConstant(&deathParams[k]);
    e.optimized = true;
  }
  const bool anyKnot = std::any_of(knotInProblem.begin(), knotInProblem.end(), [](bool b) { return b; });
  if (anyKnot && freePith) {
    const glm::dvec3 origin0(pith.origin);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<KnotGauge, 4, 6>(new KnotGauge{origin0}),
                             nullptr, pithParams.data());
  }
  if (anyKnot) {
    if (!problem.HasParameterBlock(&kStem)) {
      // Only edges (no contour near any knot): nothing to fit the smoothness to.
    } else if (options.fitSmoothness) {
      problem.SetParameterLowerBound(&kStem, 0, 0.3);
      problem.SetParameterUpperBound(&kStem, 0, 10.0);
      out.smoothnessFitted = true;
    } else {
      problem.SetParameterBlockConstant(&kStem);
    }
    ceres::Solver::Options so;
    // Each residual holds one contour's level and the few shared parameters (pith, knots, kStem): the
    // structure of bundle adjustment. The Schur complement eliminates the hundreds of levels, so a step
    // solves a dense system of the shared parameters only, instead of a QR of the whole Jacobian
    // (perf on the knot bed's dead block: the dense QR was ~60 % of the fit).
    so.linear_solver_type = ceres::DENSE_SCHUR;
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    std::vector<double*> blocks;
    problem.GetParameterBlocks(&blocks);
    const std::set<const double*> levelBlocks = [&] {
      std::set<const double*> out;
      for (const double& level : levels) out.insert(&level);
      return out;
    }();
    for (double* block : blocks) ordering->AddElementToGroup(block, levelBlocks.count(block) ? 0 : 1);
    so.linear_solver_ordering = ordering;
    so.max_num_iterations = options.maxIterations;
    so.function_tolerance = 1e-7;
    so.num_threads = 1;  // bitwise reproducible
    CeresProgress callback(progress, options.maxIterations);
    so.callbacks.push_back(&callback);
    so.update_state_every_iteration = false;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    progress.throwIfCancelled();
    out.iterations = static_cast<int>(summary.iterations.size());
  }

  std::vector<BlockKnot> fitted = initial;
  for (std::size_t k = 0; k < initial.size(); ++k) {
    if (!knotInProblem[k]) continue;
    const auto& q = knotParams[k];
    fitted[k].origin = glm::vec3(q[0], q[1], q[2]);
    fitted[k].direction = glm::normalize(glm::vec3(q[3], q[4], q[5]));
    fitted[k].speed = static_cast<float>(std::exp(q[6]));
    fitted[k].taper = static_cast<float>(taperParams[k]);
    if (initial[k].dead()) fitted[k].deathTime = static_cast<float>(deathParams[k]);
    BlockKnotFitEntry& e = out.entries[entryOf[k]];
    if (taperFree[k] && !initial[k].dead() && fitted[k].taper >= options.deadTaper) {
      // It stopped thickening between its edges (the taper runs to its bound): a dead knot (Larsson 2022
      // Sec. 4.2.2), with the section it has at its taper age, grown there at the start speed or faster.
      BlockKnot dead = fitted[k];
      dead.speed = std::max(speed0, fitted[k].speed);
      dead.taper = 0.0f;
      dead.deathTime =
          std::max(static_cast<float>(kMinDeath), fitted[k].speed * fitted[k].taperAge / dead.speed);
      fitted[k] = dead;
      e.note += "; stopped thickening (taper " + std::to_string(taperParams[k]) + "): dead from " +
                std::to_string(dead.deathTime) + " years";
    }
  }
  out.kStem = static_cast<float>(kStem);
  if (pithOut) *pithOut = pithParams;
  // With a free pith, the losses below are measured on the stem the knots were fitted with.
  std::optional<GrowthField> moved;
  if (freePith && anyKnot) {
    const PithAxis axis = PithAxis::fromDirection(glm::vec3(pithParams[0], pithParams[1], pithParams[2]),
                                                  glm::vec3(pithParams[3], pithParams[4], pithParams[5]));
    moved.emplace(axis, ringWidth, GrowthRates::uniform(block, axis));
    for (int i = 0; i < n; ++i) {
      const Cylindrical c = axis.toCylindrical(contours.points[i]);
      stemTime[i] = moved->evaluate(c);
      stemRadius[i] = c.radius;
    }
  }
  KnotSettings fittedSettings = settings;
  fittedSettings.knotSmoothStem = out.kStem;
  const BlockKnots fittedKnots(fitted, fittedSettings, stem.ringWidth(), pith.direction);
  std::vector<double> withInitial(n), withFitted(n);
  for (int i = 0; i < n; ++i) {
    const float g = static_cast<float>(stemTime[i]);
    withInitial[i] = initialKnots.merge(contours.points[i], g, stemRadius[i]).time;
    withFitted[i] = fittedKnots.merge(contours.points[i], g, stemRadius[i]).time;
  }
  for (std::size_t k = 0; k < initial.size(); ++k) {
    BlockKnotFitEntry& e = out.entries[entryOf[k]];
    e.fitted = fitted[k];
    e.axisMovedDeg = angleDeg(initial[k].direction, fitted[k].direction);
    for (const KnotMark& m : byId[e.id]) {
      const float d = knotAxisMarkDistance(&fitted[k].origin.x, &fitted[k].direction.x,
                                           faceMmToBlock(block, m.face, m.point), block.face(m.face).normal);
      if (m.released) {
        ++e.releasedMarks;
      } else {
        e.markDistanceMm = std::max(e.markDistanceMm, static_cast<double>(d));
        e.marksHeld = e.marksHeld && d <= m.accuracyMm;
      }
    }
    if (!edges[k].empty()) {
      const GrowthField& g = moved ? *moved : stem;
      const double v = fitted[k].speed;
      const glm::dvec3 o(fitted[k].origin);
      const glm::dvec3 d(fitted[k].direction);
      const double q[7] = {o.x, o.y, o.z, d.x, d.y, d.z, std::log(v)};
      const double taper = fitted[k].taper;
      const double death = fitted[k].dead() ? fitted[k].deathTime : kAliveDeath;
      std::vector<double> gaps;
      for (const glm::vec3& p : edges[k]) {
        const EdgeGeometry edge{p, ringWidth, fitted[k].taperAge, maxKnotSpeed(settings)};
        const double time = g.evaluate(g.axis().toCylindrical(p));
        gaps.push_back(std::abs(edge.gap(q, &taper, &death, time)) * ringWidth);
      }
      e.edgeDistanceMm = lowerMedian(gaps);
    }
    std::vector<bool> near(n);
    for (int c = 0; c < contours.count(); ++c)
      for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
        if (nearKnot[i] == static_cast<int>(k)) {
          ++e.contours;
          break;
        }
    for (int i = 0; i < n; ++i) {
      const float d = knotAxisDistance(&initial[k].origin.x, &initial[k].direction.x, contours.points[i]);
      near[i] = d < options.lossKnotRadii * initial[k].speed * stemRadius[i];
      e.lossPoints += near[i] ? 1 : 0;
    }
    e.lossWithout = nearKnotLoss(contours, stemTime, near);
    e.lossInitial = nearKnotLoss(contours, withInitial, near);
    e.lossFitted = nearKnotLoss(contours, withFitted, near);
  }
  out.knots = fitted;
  out.seconds = clock.seconds();
  return out;
}

}  // namespace

BlockKnotFitResult fitBlockKnots(const IsoContours& contours, const Block& block, const GrowthField& stem,
                                 const std::vector<KnotMark>& marks, const KnotSettings& settings,
                                 const BlockKnotFitOptions& options, const Progress& progress) {
  return fitKnots(contours, block, stem, marks, settings, options, progress, false, nullptr);
}

PithAndKnotsFit fitPithAndKnots(const IsoContours& contours, const Block& block, const PithAxis& pith,
                                float ringWidthMm, const std::vector<KnotMark>& marks,
                                const KnotSettings& settings, const BlockKnotFitOptions& options,
                                const Progress& progress) {
  const GrowthField undeformed(pith, ringWidthMm, GrowthRates::uniform(block, pith));
  std::array<double, 6> q{};
  PithAndKnotsFit out;
  out.knots = fitKnots(contours, block, undeformed, marks, settings, options, progress, true, &q);
  const glm::dvec3 v = glm::normalize(glm::dvec3(q[3], q[4], q[5]));
  glm::dvec3 o(q[0], q[1], q[2]);
  o -= glm::dot(o, v) * v;  // the point closest to the block centre, as the pith fit reports it
  pithAngles(glm::vec3(v), out.tiltDeg, out.azimuthDeg);
  out.pith = PithAxis::fromAngles(glm::vec3(o), out.tiltDeg, out.azimuthDeg);
  return out;
}

}  // namespace kerf
