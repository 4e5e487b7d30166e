#include "fit/pith_fit.hpp"

#include <ceres/ceres.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>

#include "fit/ceres_progress.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The frame of the axis parametrisation: e3 = principal direction, e1/e2 perpendicular.
struct Frame {
  glm::dvec3 e1, e2, e3;
  explicit Frame(glm::vec3 principal) {
    const PithAxis a = PithAxis::fromDirection(glm::vec3(0), principal);
    e3 = glm::dvec3(a.direction);
    e1 = glm::dvec3(a.reference);
    e2 = glm::cross(e3, e1);
  }
  glm::dvec3 local(glm::vec3 p) const {
    const glm::dvec3 q(p);
    return {glm::dot(q, e1), glm::dot(q, e2), glm::dot(q, e3)};
  }
};

// x = (u, v, a, b): the axis crosses the plane e3 = 0 at u e1 + v e2 and runs along a e1 + b e2 + e3.
template <typename T>
T axisDistance(const T* x, const glm::dvec3& p) {
  const T w1 = p.x - x[0], w2 = p.y - x[1], w3 = T(p.z);
  const T dd = x[2] * x[2] + x[3] * x[3] + T(1.0);
  const T wd = w1 * x[2] + w2 * x[3] + w3;
  T d2 = w1 * w1 + w2 * w2 + w3 * w3 - wd * wd / dd;
  if (d2 < T(1e-12)) d2 = T(1e-12);
  using std::sqrt;
  return sqrt(d2);
}

std::array<double, 4> paramsFromAxis(const Frame& fr, const PithAxis& axis) {
  const glm::dvec3 o(axis.origin), d(axis.direction);
  double d3 = glm::dot(d, fr.e3);
  if (std::abs(d3) < 1e-6) d3 = d3 < 0 ? -1e-6 : 1e-6;
  const glm::dvec3 dir = d / d3;         // e3 component 1
  const double t = -glm::dot(o, fr.e3);  // o + t * dir lies on the plane e3 = 0
  const glm::dvec3 p = o + t * dir;
  return {glm::dot(p, fr.e1), glm::dot(p, fr.e2), glm::dot(dir, fr.e1), glm::dot(dir, fr.e2)};
}

PithAxis axisFromParams(const Frame& fr, const double* x) {
  const glm::dvec3 p = x[0] * fr.e1 + x[1] * fr.e2;
  glm::dvec3 d = glm::normalize(x[2] * fr.e1 + x[3] * fr.e2 + fr.e3);
  const glm::dvec3 q = p - glm::dot(p, d) * d;  // closest to the block centre
  if (d.y < 0) d = -d;
  return PithAxis::fromDirection(glm::vec3(q), glm::vec3(d));
}

// Contour points in frame coordinates, and the evenly subsampled set the continuous fit uses.
struct Samples {
  std::vector<glm::dvec3> p;
  std::vector<int> contour;
  std::vector<int> begin;  // per contour, into p
};

Samples subsample(const IsoContours& contours, const Frame& fr, int maxTotal, int perContourMax) {
  Samples s;
  const int total = static_cast<int>(contours.points.size());
  const int stride = std::max(1, (total + maxTotal - 1) / std::max(1, maxTotal));
  for (int c = 0; c < contours.count(); ++c) {
    s.begin.push_back(static_cast<int>(s.p.size()));
    const int n = contours.size(c);
    int step = stride;
    if (perContourMax > 0) step = std::max(1, n / perContourMax);
    step = std::min(step, std::max(1, n / 2));  // at least two points per contour
    for (int i = step / 2; i < n; i += step) {
      s.p.push_back(fr.local(contours.points[contours.begin[c] + i]));
      s.contour.push_back(c);
      if (perContourMax > 0 && static_cast<int>(s.p.size()) - s.begin.back() >= perContourMax) break;
    }
  }
  s.begin.push_back(static_cast<int>(s.p.size()));
  return s;
}

// Loss of the median form (per face mean |d - med_c|, mean over faces) on a subsample.
double sampledLoss(const Samples& s, const IsoContours& contours, const double* x, std::vector<double>& d) {
  std::array<double, 6> sum{};
  std::array<int, 6> count{};
  d.resize(s.p.size());
  for (std::size_t i = 0; i < s.p.size(); ++i) d[i] = axisDistance(x, s.p[i]);
  std::vector<double> tmp;
  for (int c = 0; c + 1 < static_cast<int>(s.begin.size()); ++c) {
    const int b = s.begin[c], e = s.begin[c + 1];
    if (e <= b) continue;
    tmp.assign(d.begin() + b, d.begin() + e);
    const double med = lowerMedian(tmp);
    const int f = faceIndex(contours.face[c]);
    for (int i = b; i < e; ++i) sum[f] += std::abs(d[i] - med);
    count[f] += e - b;
  }
  double total = 0;
  int faces = 0;
  for (int f = 0; f < 6; ++f)
    if (count[f]) total += sum[f] / count[f], ++faces;
  return faces ? total / faces : 0.0;
}

// All contour points' residuals rho(dist - level_c) as one Ceres cost: parameter blocks (u, v, a, b)
// and the N levels. Evaluated in parallel over fixed chunks (deterministic).
class ContourCost final : public ceres::CostFunction {
 public:
  ContourCost(const Samples& s, int levels, double scale) : s_(s), levels_(levels), b2_(scale * scale) {
    set_num_residuals(static_cast<int>(s.p.size()));
    mutable_parameter_block_sizes()->push_back(4);
    mutable_parameter_block_sizes()->push_back(levels);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double* x = parameters[0];
    const double* level = parameters[1];
    const int n = num_residuals();
    constexpr int kChunk = 512;
    const int chunks = (n + kChunk - 1) / kChunk;
    parallelRows(chunks, [&](int k) {
      using J = ceres::Jet<double, 4>;
      J xj[4];
      for (int j = 0; j < 4; ++j) xj[j] = J(x[j], j);
      const int end = std::min(n, (k + 1) * kChunk);
      for (int i = k * kChunk; i < end; ++i) {
        const int c = s_.contour[i];
        double dist;
        J dj;
        if (jacobians && jacobians[0]) {
          dj = axisDistance(xj, s_.p[i]);
          dist = dj.a;
        } else {
          dist = axisDistance(x, s_.p[i]);
        }
        const double r = dist - level[c];
        // soft-L1 as a residual: f^2 = 2 b^2 (sqrt(1 + r^2/b^2) - 1), f ~ r near 0.
        const double sq = std::sqrt(1.0 + r * r / b2_);
        const double kf = std::sqrt(2.0 / (sq + 1.0));
        residuals[i] = r * kf;
        if (jacobians) {
          const double df = kf - r * r / (kf * (sq + 1.0) * (sq + 1.0) * b2_ * sq);
          if (jacobians[0]) {
            for (int j = 0; j < 4; ++j) jacobians[0][i * 4 + j] = df * dj.v[j];
          }
          if (jacobians[1]) {
            double* row = jacobians[1] + static_cast<std::size_t>(i) * levels_;
            std::fill(row, row + levels_, 0.0);
            row[c] = -df;
          }
        }
      }
    });
    return true;
  }

 private:
  const Samples& s_;
  int levels_;
  double b2_;
};

// The anatomical prior's weight and fibre direction in frame coordinates; weight 0 without one.
struct Prior {
  double weight = 0;  // anatomyWeight * confidence
  glm::dvec3 fibre{0, 0, 1};
  Prior(const Frame& fr, const PithFitOptions& o) {
    if (!o.anatomy || o.anatomyWeight <= 0) return;
    weight = o.anatomyWeight * o.anatomy->confidence;
    const glm::dvec3 f(o.anatomy->fibre);
    fibre = {glm::dot(f, fr.e1), glm::dot(f, fr.e2), glm::dot(f, fr.e3)};
  }
  // 1 - (V.F)^2 of the direction (a, b, 1) in frame coordinates.
  double sin2(const double* x) const {
    const glm::dvec3 v = glm::normalize(glm::dvec3(x[2], x[3], 1.0));
    const double c = glm::dot(v, fibre);
    return 1.0 - c * c;
  }
};

// sqrt(k) * (V x F) with V = (a, b, 1) / |(a, b, 1)|: half its squared norm is k/2 * (1 - (V.F)^2).
struct PriorResidual {
  double sqrtK;
  glm::dvec3 f;
  template <typename T>
  bool operator()(const T* x, T* r) const {
    using std::sqrt;
    const T n = sqrt(x[2] * x[2] + x[3] * x[3] + T(1.0));
    const T v0 = x[2] / n, v1 = x[3] / n, v2 = T(1.0) / n;
    r[0] = sqrtK * (v1 * f.z - v2 * f.y);
    r[1] = sqrtK * (v2 * f.x - v0 * f.z);
    r[2] = sqrtK * (v0 * f.y - v1 * f.x);
    return true;
  }
};

// Zero while the axis crosses the frame's plane within dMax of the block centre, then sqrt(k) * (d - dMax)
// / dMax: half its square is k/2 per dMax of excess squared, k as for the anatomical prior.
struct DistancePriorResidual {
  double sqrtK, dMax;
  template <typename T>
  bool operator()(const T* x, T* r) const {
    using std::sqrt;
    const T d = sqrt(x[0] * x[0] + x[1] * x[1] + T(1e-12));
    r[0] = d > T(dMax) ? sqrtK * (d - T(dMax)) / T(dMax) : T(0.0);
    return true;
  }
};

struct Refined {
  std::array<double, 4> x;
  double cost;
  int iterations;
};

Refined refineParams(const Samples& s, int levels, std::array<double, 4> x, const PithFitOptions& options,
                     const Progress& progress, const Prior& prior) {
  // Levels start at each contour's median distance.
  std::vector<double> level(levels, 0.0), tmp;
  for (int c = 0; c < levels; ++c) {
    tmp.clear();
    for (int i = s.begin[c]; i < s.begin[c + 1]; ++i) tmp.push_back(axisDistance(x.data(), s.p[i]));
    level[c] = lowerMedian(tmp);
  }
  ceres::Problem::Options po;
  po.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  auto* contourCost = new ContourCost(s, levels, options.robustScaleMm);
  problem.AddResidualBlock(contourCost, nullptr, x.data(), level.data());
  if (prior.weight > 0 || options.plausibleDistanceMm > 0) {
    // The priors are scaled by the contour cost at the start, so their pull does not depend on how many
    // points there are: the anatomical one adds weight * sin^2 of that cost.
    std::vector<double> res(s.p.size());
    const double* params[2] = {x.data(), level.data()};
    contourCost->Evaluate(params, res.data(), nullptr);
    double cost0 = 0;
    for (double r : res) cost0 += 0.5 * r * r;
    if (prior.weight > 0)
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorResidual, 3, 4>(
                                   new PriorResidual{std::sqrt(2.0 * prior.weight * cost0), prior.fibre}),
                               nullptr, x.data());
    if (options.plausibleDistanceMm > 0)
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<DistancePriorResidual, 1, 4>(
              new DistancePriorResidual{std::sqrt(2.0 * cost0), options.plausibleDistanceMm}),
          nullptr, x.data());
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;  // robust where the normal equations are ill-conditioned
  so.minimizer_type = ceres::TRUST_REGION;
  so.max_num_iterations = options.maxIterations;
  // A far pith lies in a long flat valley of the loss (the origin slides along it at equal loss):
  // tighter tolerances only creep along it. 1e-7 halves the refinement time on CN03 against 1e-10 with
  // the same loss to 4 digits.
  so.function_tolerance = 1e-7;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-8;
  so.num_threads = 1;  // the cost parallelises itself, deterministically
  CeresProgress stop(progress);
  so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  progress.throwIfCancelled();
  return {x, summary.final_cost, static_cast<int>(summary.iterations.size())};
}

PithCandidate makeCandidate(const IsoContours& contours, const Frame& fr, const Refined& r,
                            const PithFitOptions& options) {
  PithCandidate c;
  c.axis = axisFromParams(fr, r.x.data());
  pithAngles(c.axis.direction, c.tiltDeg, c.azimuthDeg);
  const PithAxis axis = c.axis;
  c.loss = isoContourLoss(
      contours, [&axis](glm::vec3 p) { return static_cast<double>(axis.toCylindrical(p).radius); }, 0.0);
  c.solverCost = r.cost;
  c.iterations = r.iterations;
  if (options.anatomy) c.anatomyPenalty = anatomyPenalty(*options.anatomy, c.axis.direction);
  c.score = c.loss.meanOverFaces * (1.0 + std::max(0.0, options.anatomyWeight) * c.anatomyPenalty);
  return c;
}

double angleDeg(glm::vec3 a, glm::vec3 b) {
  const double c = std::abs(glm::dot(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b))));
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

// Distance between two axes near the block: the larger distance of each one's closest-to-centre point
// from the other line.
double axisSeparationMm(const PithAxis& a, const PithAxis& b) {
  return std::max(a.toCylindrical(b.origin).radius, b.toCylindrical(a.origin).radius);
}

}  // namespace

void pithAngles(glm::vec3 direction, float& tiltDeg, float& azimuthDeg) {
  glm::dvec3 d = glm::normalize(glm::dvec3(direction));
  if (d.y < 0) d = -d;
  tiltDeg = static_cast<float>(std::acos(std::clamp(d.y, -1.0, 1.0)) * 180.0 / std::numbers::pi);
  const double s = std::hypot(d.x, d.z);
  azimuthDeg = s < 1e-9 ? 0.0f : static_cast<float>(std::atan2(-d.z, d.x) * 180.0 / std::numbers::pi);
}

PithCandidate refinePith(const IsoContours& contours, const Block&, const PithAxis& start,
                         const PithFitOptions& options, const Progress& progress) {
  if (contours.count() == 0) throw InputError("no ring contours to fit the pith to");
  const Frame fr(options.principal);
  const Samples fit = subsample(contours, fr, options.maxFitPoints, 0);
  return makeCandidate(
      contours, fr,
      refineParams(fit, contours.count(), paramsFromAxis(fr, start), options, progress, Prior(fr, options)),
      options);
}

PithFitResult fitPith(const IsoContours& contours, const Block& block, const PithFitOptions& options,
                      const Progress& progress) {
  PithFitResult result;
  result.contours = contours.count();
  result.points = static_cast<int>(contours.points.size());
  if (contours.count() == 0) throw InputError("no ring contours to fit the pith to");
  if (contours.count() < 4) {
    result.warnings.push_back("only " + std::to_string(contours.count()) +
                              " contours: the pith axis is poorly constrained");
  }
  if (contours.facesWithContours() < 2) {
    result.warnings.push_back("all contours lie on one face: the pith direction is poorly constrained");
  }
  const Frame fr(options.principal);
  const Prior prior(fr, options);

  // 1. Grid search.
  const auto t0 = Clock::now();
  std::vector<std::array<double, 4>> grid;
  const double maxTilt = options.maxTiltDeg * std::numbers::pi / 180.0;
  const double step = std::max(0.5, static_cast<double>(options.tiltStepDeg)) * std::numbers::pi / 180.0;
  std::vector<std::array<double, 2>> directions;  // (a, b)
  for (double t = 0; t <= maxTilt + 1e-9; t += step) {
    const int n =
        t < 1e-9 ? 1 : std::max(4, static_cast<int>(std::round(2 * std::numbers::pi * std::sin(t) / step)));
    for (int k = 0; k < n; ++k) {
      const double phi = 2 * std::numbers::pi * k / n;
      directions.push_back({std::tan(t) * std::cos(phi), std::tan(t) * std::sin(phi)});
    }
  }
  for (const auto& ab : directions) {
    for (std::size_t id = 0; id < options.distancesMm.size(); ++id) {
      const double dist = options.distancesMm[id];
      const int n = dist <= 0 ? 1 : options.originAngles;
      for (int k = 0; k < n; ++k) {
        // Alternate distances are staggered by half a step around the circle.
        const double phi = 2 * std::numbers::pi * (k + 0.5 * static_cast<double>(id % 2)) / n;
        grid.push_back({dist * std::cos(phi), dist * std::sin(phi), ab[0], ab[1]});
      }
    }
  }
  result.gridCandidates = static_cast<int>(grid.size());
  const Samples coarse = subsample(contours, fr, 0, options.gridPointsPerContour);
  std::vector<double> gridLoss(grid.size());
  constexpr int kChunk = 256;
  const int chunks = static_cast<int>((grid.size() + kChunk - 1) / kChunk);
  Progress gridProgress;
  gridProgress.stop = progress.stop;
  gridProgress.report = [&progress](double f) { progress.set(0.4 * f); };
  parallelRows(
      chunks,
      [&](int k) {
        std::vector<double> d;
        const std::size_t end = std::min(grid.size(), static_cast<std::size_t>(k + 1) * kChunk);
        for (std::size_t i = static_cast<std::size_t>(k) * kChunk; i < end; ++i)
          gridLoss[i] = sampledLoss(coarse, contours, grid[i].data(), d) *
                        (1.0 + prior.weight * prior.sin2(grid[i].data()));
      },
      gridProgress);
  std::vector<int> order(grid.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return gridLoss[a] < gridLoss[b]; });
  // Distinct candidates: at least 4 degrees or 5 mm apart.
  std::vector<PithAxis> starts;
  for (int i : order) {
    const PithAxis a = axisFromParams(fr, grid[i].data());
    bool distinct = true;
    for (const PithAxis& s : starts)
      if (angleDeg(a.direction, s.direction) < 4.0 && axisSeparationMm(a, s) < 5.0) distinct = false;
    if (distinct) starts.push_back(a);
    if (static_cast<int>(starts.size()) >= options.refineCandidates) break;
  }
  result.gridSeconds = secondsSince(t0);

  // 2. Continuous refinement of each start.
  const auto t1 = Clock::now();
  const Samples fit = subsample(contours, fr, options.maxFitPoints, 0);
  result.fitPoints = static_cast<int>(fit.p.size());
  const int slots = static_cast<int>(starts.size()) + 1;
  // The starts are independent: refined side by side (each on one thread; the cost's own parallel loop
  // runs serially inside), so the result does not depend on the number of threads.
  std::vector<PithCandidate> refined(starts.size());
  std::atomic<int> finished{0};
  const Progress quiet{nullptr, progress.stop};
  std::vector<std::exception_ptr> failures(starts.size());  // not thrown across the thread pool
  parallelRows(static_cast<int>(starts.size()), [&](int i) {
    try {
      const Refined r =
          refineParams(fit, contours.count(), paramsFromAxis(fr, starts[i]), options, quiet, prior);
      refined[i] = makeCandidate(contours, fr, r, options);
      progress.set(0.4 + 0.6 * static_cast<double>(++finished) / slots);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  });
  progress.throwIfCancelled();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  std::size_t bestIndex = 0;
  for (std::size_t i = 1; i < refined.size(); ++i)
    if (refined[i].score < refined[bestIndex].score) bestIndex = i;
  result.best = refined[bestIndex];

  // 3. Flip ambiguity: mirror the axis through the plane through the centre perpendicular to the
  // direction of the pith, refine, compare.
  const glm::vec3 q = result.best.axis.origin;
  if (glm::length(q) > 1e-3f) {
    const glm::vec3 n = glm::normalize(q);
    const glm::vec3 v = result.best.axis.direction;
    const PithAxis mirrored = PithAxis::fromDirection(-q, v - 2.0f * glm::dot(v, n) * n);
    const Refined r =
        refineParams(fit, contours.count(), paramsFromAxis(fr, mirrored), options, progress, prior);
    PithCandidate flipped = makeCandidate(contours, fr, r, options);
    // Also consider refined grid candidates that lie on the other side of the block.
    for (const PithCandidate& c : refined) {
      if (glm::dot(c.axis.origin, q) < 0 && c.score < flipped.score) flipped = c;
    }
    const bool distinct =
        angleDeg(flipped.axis.direction, v) > 2.0 || axisSeparationMm(flipped.axis, result.best.axis) > 2.0;
    if (distinct && flipped.score < result.best.score) std::swap(flipped, result.best);
    if (distinct) {
      result.ambiguous = flipped.score <= options.ambiguityRatio * result.best.score;
      result.flipped = flipped;
    }
  }
  progress.set(1.0);
  result.refineSeconds = secondsSince(t1);
  return result;
}

RingLevelEstimate estimateRingLevels(const PithAxis& axis, const Block& block,
                                     const std::array<GrayImage8, 6>& images) {
  return estimateRingLevels(
      [&axis](glm::vec3 p) { return static_cast<double>(axis.toCylindrical(p).radius); }, block, images);
}

RingLevelEstimate estimateRingLevels(const std::function<double(glm::vec3)>& distanceMm, const Block& block,
                                     const std::array<GrayImage8, 6>& images) {
  constexpr double kBin = 0.05;
  double rMin = 1e30, rMax = -1e30;
  struct Sample {
    float r;
    float v;
  };
  std::vector<Sample> samples;
  for (FaceId f : kAllFaces) {
    const GrayImage8& im = images[faceIndex(f)];
    if (im.empty()) continue;
    const glm::ivec2 size(im.width, im.height);
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        const float r = static_cast<float>(distanceMm(block.pixelCenter(f, x, y, size)));
        samples.push_back({r, im.at(x, y) / 255.0f});
        rMin = std::min(rMin, static_cast<double>(r)), rMax = std::max(rMax, static_cast<double>(r));
      }
  }
  if (samples.empty()) throw InputError("no ring-localization image to place the rings with");
  const int bins = static_cast<int>((rMax - rMin) / kBin) + 1;
  std::vector<double> sum(bins, 0.0), count(bins, 0.0);
  for (const Sample& s : samples) {
    const int b = std::min(bins - 1, static_cast<int>((s.r - rMin) / kBin));
    sum[b] += s.v, count[b] += 1;
  }
  // Smooth over +-3 bins (0.3 mm window), weighted by counts.
  std::vector<double> bar(bins, 0.0);
  std::vector<char> valid(bins, 0);
  double mean = 0;
  int nValid = 0;
  for (int b = 0; b < bins; ++b) {
    double s = 0, c = 0;
    for (int k = std::max(0, b - 3); k <= std::min(bins - 1, b + 3); ++k) s += sum[k], c += count[k];
    if (c > 0) bar[b] = s / c, valid[b] = 1, mean += bar[b], ++nValid;
  }
  mean /= std::max(1, nValid);
  RingLevelEstimate est;
  int start = -1;
  for (int b = 0; b <= bins; ++b) {
    const bool above = b < bins && valid[b] && bar[b] >= mean;
    if (above && start < 0) start = b;
    if (!above && start >= 0) {
      est.peaksMm.push_back(static_cast<float>(rMin + kBin * (0.5 * (start + b))));
      start = -1;
    }
  }
  if (est.peaksMm.size() < 2) throw InputError("fewer than two rings found along the fitted pith axis");
  std::vector<double> gaps;
  for (std::size_t i = 1; i < est.peaksMm.size(); ++i) gaps.push_back(est.peaksMm[i] - est.peaksMm[i - 1]);
  const double spacing = lowerMedian(gaps);
  est.medianSpacingMm = static_cast<float>(spacing);
  // Whole ring numbers from the median spacing, then a least-squares line peak = a + w k.
  std::vector<double> k(est.peaksMm.size());
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = std::round((est.peaksMm[i] - est.peaksMm[0]) / spacing);
  const double n = static_cast<double>(k.size());
  double sk = 0, sp = 0, skk = 0, skp = 0;
  for (std::size_t i = 0; i < k.size(); ++i)
    sk += k[i], sp += est.peaksMm[i], skk += k[i] * k[i], skp += k[i] * est.peaksMm[i];
  const double den = n * skk - sk * sk;
  const double w = den > 1e-12 ? (n * skp - sk * sp) / den : spacing;
  const double a = (sp - w * sk) / n;
  est.ringWidthMm = static_cast<float>(w > 0 ? w : spacing);
  const double phase = a / est.ringWidthMm;
  est.ringOffset = static_cast<float>(phase - std::floor(phase));
  return est;
}

}  // namespace kerf
