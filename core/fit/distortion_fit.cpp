#include "fit/distortion_fit.hpp"

#include <ceres/ceres.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>

#include "field/bspline.hpp"
#include "field/growth_field.hpp"
#include "fit/ceres_progress.hpp"
#include "fit/gray_map.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

namespace {

// Coefficients grouped by column (ih * azimuths + ia): radii weights per column.
std::map<int, std::vector<double>> columnCoefficients(const GrowthRates& g, const PithAxis& axis,
                                                      float ringWidth, glm::vec3 p) {
  const Cylindrical c = axis.toCylindrical(p);
  const int nr = g.radii;
  const GridStencil stencil = gridStencil(g, c.height, c.azimuth);

  // Radial coefficients of one column (shared by all 16 columns: they depend on r only).
  std::vector<double> radial(nr, 0.0);
  const double r = c.radius, step = (g.radiusMax - g.radiusMin) / nr;
  if (r <= g.radiusMin) {
    if (g.radiusMin > 0) radial[0] = r;
  } else {
    const double f = (r - g.radiusMin) / step;
    radial[0] += g.radiusMin;
    if (f >= nr) {
      for (int k = 0; k < nr; ++k) radial[k] += step;
      radial[nr - 1] += r - g.radiusMax;
    } else {
      const int ir = static_cast<int>(f);
      for (int k = 0; k < ir; ++k) radial[k] += step;
      radial[ir] += (f - ir) * step;
    }
  }
  for (double& v : radial) v /= ringWidth;

  std::map<int, std::vector<double>> columns;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double w = static_cast<double>(stencil.heightWeights[i]) * stencil.spokeWeights[j];
      if (w == 0.0) continue;
      auto& col = columns[stencil.heights[i] * g.azimuths + stencil.spokes[j]];
      if (col.empty()) col.assign(nr, 0.0);
      for (int k = 0; k < nr; ++k) col[k] += w * radial[k];
    }
  }
  return columns;
}

// A residual of G(p) = sum_k A_k exp(s_k) over the columns a point touches: the value and the
// Jacobian of G in s, shared by the contour and image residuals.
class RateResidual : public ceres::CostFunction {
 protected:
  RateResidual(std::vector<std::vector<double>> weights, int radii, int extraBlocks)
      : w_(std::move(weights)), radii_(radii) {
    set_num_residuals(1);
    for (std::size_t i = 0; i < w_.size(); ++i) mutable_parameter_block_sizes()->push_back(radii);
    for (int i = 0; i < extraBlocks; ++i) mutable_parameter_block_sizes()->push_back(1);
  }
  int columns() const { return static_cast<int>(w_.size()); }
  double field(double const* const* s) const {
    double g = 0;
    for (int b = 0; b < columns(); ++b)
      for (int k = 0; k < radii_; ++k)
        if (w_[b][k] != 0.0) g += w_[b][k] * std::exp(s[b][k]);
    return g;
  }
  // jacobians[b] = dG/ds_b * factor for the column blocks.
  void fieldJacobian(double const* const* s, double factor, double** jacobians) const {
    for (int b = 0; b < columns(); ++b) {
      if (!jacobians[b]) continue;
      for (int k = 0; k < radii_; ++k)
        jacobians[b][k] = w_[b][k] != 0.0 ? factor * w_[b][k] * std::exp(s[b][k]) : 0.0;
    }
  }

 private:
  std::vector<std::vector<double>> w_;
  int radii_;
};

// One contour point: rho(G(p) - level), soft-L1.
class PointCost final : public RateResidual {
 public:
  PointCost(std::vector<std::vector<double>> weights, int radii, double scale, double sqrtWeight)
      : RateResidual(std::move(weights), radii, 1), b2_(scale * scale), sw_(sqrtWeight) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int n = columns();
    const double r = field(parameters) - parameters[n][0];
    const double sq = std::sqrt(1.0 + r * r / b2_), kf = std::sqrt(2.0 / (sq + 1.0));
    residuals[0] = sw_ * r * kf;
    if (jacobians) {
      const double df = sw_ * (kf - r * r / (kf * (sq + 1.0) * (sq + 1.0) * b2_ * sq));
      fieldJacobian(parameters, df, jacobians);
      if (jacobians[n]) jacobians[n][0] = -df;
    }
    return true;
  }

 private:
  double b2_, sw_;
};

// One face pixel of the image term (Mokume Eq. 5): w (M(G(p)) - target), M fixed.
class ImageCost final : public RateResidual {
 public:
  ImageCost(std::vector<std::vector<double>> weights, int radii, const GrayMap* map, double target, double w)
      : RateResidual(std::move(weights), radii, 0), map_(map), target_(target), sw_(w) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double g = field(parameters);
    residuals[0] = sw_ * (map_->value(g) - target_);
    if (jacobians) fieldJacobian(parameters, sw_ * map_->slope(g), jacobians);
    return true;
  }

 private:
  const GrayMap* map_;
  double target_, sw_;
};

class LinearDifference final : public ceres::CostFunction {
 public:
  // Two blocks: w (a_k - b_k); one block: w (a_{k+1} - a_k).
  LinearDifference(int n, bool twoBlocks, double w) : n_(n), two_(twoBlocks), w_(w) {
    set_num_residuals(two_ ? n : n - 1);
    mutable_parameter_block_sizes()->push_back(n);
    if (two_) mutable_parameter_block_sizes()->push_back(n);
  }
  bool Evaluate(double const* const* p, double* r, double** j) const override {
    const int m = num_residuals();
    for (int k = 0; k < m; ++k) r[k] = two_ ? w_ * (p[0][k] - p[1][k]) : w_ * (p[0][k + 1] - p[0][k]);
    if (j) {
      for (int b = 0; b < (two_ ? 2 : 1); ++b) {
        if (!j[b]) continue;
        std::fill(j[b], j[b] + static_cast<std::size_t>(m) * n_, 0.0);
        for (int k = 0; k < m; ++k) {
          if (two_) {
            j[b][k * n_ + k] = b == 0 ? w_ : -w_;
          } else {
            j[b][k * n_ + k] = -w_;
            j[b][k * n_ + k + 1] = w_;
          }
        }
      }
    }
    return true;
  }

 private:
  int n_;
  bool two_;
  double w_;
};

// w * s for one block.
class Ridge final : public ceres::CostFunction {
 public:
  Ridge(int n, double w) : n_(n), w_(w) {
    set_num_residuals(n);
    mutable_parameter_block_sizes()->push_back(n);
  }
  bool Evaluate(double const* const* p, double* r, double** j) const override {
    for (int k = 0; k < n_; ++k) r[k] = w_ * p[0][k];
    if (j && j[0]) {
      std::fill(j[0], j[0] + static_cast<std::size_t>(n_) * n_, 0.0);
      for (int k = 0; k < n_; ++k) j[0][k * n_ + k] = w_;
    }
    return true;
  }

 private:
  int n_;
  double w_;
};

}  // namespace

std::vector<RateCoefficient> growthCoefficients(const GrowthRates& layout, const PithAxis& axis,
                                                float ringWidthMm, glm::vec3 p) {
  std::vector<RateCoefficient> out;
  for (const auto& [col, w] : columnCoefficients(layout, axis, ringWidthMm, p))
    for (int k = 0; k < layout.radii; ++k)
      if (w[k] != 0.0) out.push_back({col * layout.radii + k, w[k]});
  return out;
}

namespace {

// G at a point from its column coefficients and the log-rates s.
double fieldValue(const std::map<int, std::vector<double>>& columns, const std::vector<double>& s, int nr) {
  double g = 0;
  for (const auto& [col, w] : columns)
    for (int k = 0; k < nr; ++k)
      if (w[k] != 0.0) g += w[k] * std::exp(s[static_cast<std::size_t>(col) * nr + k]);
  return g;
}

}  // namespace

DistortionFitResult fitDistortions(const IsoContours& contours, const Block& block, const PithAxis& axis,
                                   float ringWidthMm, const DistortionFitOptions& options,
                                   const Progress& progress, const std::array<GrayImage8, 6>* ringImages) {
  if (contours.count() == 0) throw InputError("no ring contours to fit the growth rates to");
  const auto t0 = std::chrono::steady_clock::now();
  DistortionFitResult result;
  GrowthRates layout = GrowthRates::uniform(block, axis, options.heights, options.azimuths, options.radii,
                                            GrowthRates::Azimuths::Block);
  const int nr = layout.radii, columns = layout.heights * layout.azimuths;
  result.lossBefore = isoContourLoss(contours, GrowthField(axis, ringWidthMm, layout), 1.0);

  std::vector<double> s(static_cast<std::size_t>(columns) * nr, 0.0);
  std::vector<double> level(contours.count(), 0.0);
  // Evenly subsampled points.
  const int total = static_cast<int>(contours.points.size());
  const int stride = std::max(1, (total + options.maxFitPoints - 1) / std::max(1, options.maxFitPoints));
  std::vector<int> pointIndex, pointContour;
  for (int c = 0; c < contours.count(); ++c) {
    const int n = contours.size(c);
    const int step = std::min(stride, std::max(1, n / 2));
    for (int i = step / 2; i < n; i += step)
      pointIndex.push_back(contours.begin[c] + i), pointContour.push_back(c);
  }
  const int m = static_cast<int>(pointIndex.size());
  std::vector<std::map<int, std::vector<double>>> coefficients(m);
  parallelRows(m, [&](int i) {
    coefficients[i] = columnCoefficients(layout, axis, ringWidthMm, contours.points[pointIndex[i]]);
  });
  // Levels start at each contour's median value of the undeformed field.
  {
    std::vector<std::vector<double>> values(contours.count());
    for (int i = 0; i < m; ++i) values[pointContour[i]].push_back(fieldValue(coefficients[i], s, nr));
    for (int c = 0; c < contours.count(); ++c) level[c] = lowerMedian(values[c]);
  }
  ceres::Problem problem;
  const double sw = 1.0 / std::sqrt(static_cast<double>(m));
  auto addFieldResidual = [&](const std::map<int, std::vector<double>>& columnsOfPoint, auto makeCost,
                              double* extraBlock) {
    std::vector<std::vector<double>> weights;
    std::vector<double*> blocks;
    for (const auto& [col, w] : columnsOfPoint) {
      weights.push_back(w);
      blocks.push_back(&s[static_cast<std::size_t>(col) * nr]);
    }
    if (extraBlock) blocks.push_back(extraBlock);
    problem.AddResidualBlock(makeCost(std::move(weights)), nullptr, blocks);
  };
  for (int i = 0; i < m; ++i)
    addFieldResidual(
        coefficients[i],
        [&](std::vector<std::vector<double>> w) {
          return new PointCost(std::move(w), nr, options.robustScaleYears, sw);
        },
        &level[pointContour[i]]);
  // Smoothness: neighbouring spokes (periodic on the full circle), heights, radial cells.
  const int pairs = columns * 2 + columns;
  const bool periodic = layout.fullCircle();
  const double ws = std::sqrt(options.smoothness / (static_cast<double>(pairs) * nr));
  auto col = [&](int h, int a) { return &s[static_cast<std::size_t>(h * layout.azimuths + a) * nr]; };
  for (int h = 0; h < layout.heights; ++h)
    for (int a = 0; a < layout.azimuths; ++a) {
      if (periodic || a + 1 < layout.azimuths)
        problem.AddResidualBlock(new LinearDifference(nr, true, ws), nullptr, col(h, a),
                                 col(h, (a + 1) % layout.azimuths));
      if (h + 1 < layout.heights)
        problem.AddResidualBlock(new LinearDifference(nr, true, ws), nullptr, col(h, a), col(h + 1, a));
      if (nr > 1) problem.AddResidualBlock(new LinearDifference(nr, false, ws), nullptr, col(h, a));
    }
  // Ridge towards uniform rates (s = 0), per column: keeps the scale of G from drifting (a smaller G makes
  // every contour residual smaller) without the dense coupling of a hard mean constraint.
  const double wr = std::sqrt(options.ridge / (static_cast<double>(columns) * nr));
  for (int c = 0; c < columns; ++c)
    problem.AddResidualBlock(new Ridge(nr, wr), nullptr, &s[static_cast<std::size_t>(c) * nr]);

  // The image term's samples: every imageStride-th pixel of each face's ring-localization image.
  std::vector<std::map<int, std::vector<double>>> pixelCoefficients;
  std::vector<double> pixelTarget;
  if (ringImages && options.imageWeight > 0) {
    std::vector<glm::vec3> points;
    for (FaceId f : kAllFaces) {
      const GrayImage8& im = (*ringImages)[faceIndex(f)];
      if (im.empty()) continue;
      const int st = std::max(1, options.imageStride);
      for (int y = st / 2; y < im.height; y += st)
        for (int x = st / 2; x < im.width; x += st) {
          points.push_back(block.pixelCenter(f, x, y, {im.width, im.height}));
          pixelTarget.push_back(im.at(x, y) / 255.0);
        }
    }
    pixelCoefficients.resize(points.size());
    parallelRows(static_cast<int>(points.size()), [&](int i) {
      pixelCoefficients[i] = columnCoefficients(layout, axis, ringWidthMm, points[i]);
    });
  }
  const int pixels = static_cast<int>(pixelTarget.size());
  auto pixelValues = [&] {
    std::vector<double> g(pixels);
    parallelRows(pixels, [&](int i) { g[i] = fieldValue(pixelCoefficients[i], s, nr); });
    return g;
  };

  ceres::Solver::Options so;
  // Inexact steps by conjugate gradients on the normal equations: every point touches 16 columns x 16
  // radial cells (the rates are integrated along the radius), so J^T J is half dense and its sparse
  // Cholesky took ~0.3 s per step on CN03; 30 CG iterations per step reach the same loss 2-3x faster.
  so.linear_solver_type = ceres::CGNR;
  so.max_linear_solver_iterations = 30;
  so.function_tolerance = 1e-6;
  so.num_threads = 1;  // bitwise reproducible (Ceres sums costs per thread)
  const int rounds = pixels > 0 ? 1 + std::max(1, options.imageRounds) : 1;
  const int totalIterations = options.maxIterations + (rounds - 1) * options.imageIterations;
  int done = 0;
  GrayMap map;
  for (int round = 0; round < rounds; ++round) {
    if (round == 1) {
      // From now on with the image term: M is fitted in closed form for the current field (fit/gray_map),
      // then held fixed while the rates move; ImageCost reads `map`, refitted before every round.
      map = fitGrayMap(pixelValues(), pixelTarget, options.grayMapBins, options.grayMapRidge);
      result.imageLossBefore = grayMapImageLoss(map, pixelValues(), pixelTarget);
      const double wi = std::sqrt(options.imageWeight / static_cast<double>(pixels));
      for (int i = 0; i < pixels; ++i)
        addFieldResidual(
            pixelCoefficients[i],
            [&](std::vector<std::vector<double>> w) {
              return new ImageCost(std::move(w), nr, &map, pixelTarget[i], wi);
            },
            nullptr);
    } else if (round > 1) {
      map = fitGrayMap(pixelValues(), pixelTarget, options.grayMapBins, options.grayMapRidge);
    }
    const int iterations = round == 0 ? options.maxIterations : options.imageIterations;
    so.max_num_iterations = iterations;
    const Progress sub{progress.report ? std::function<void(double)>([&, done, iterations](double f) {
                         progress.set((done + f * iterations) / totalIterations);
                       })
                                       : std::function<void(double)>(),
                       progress.stop};
    CeresProgress callback(sub, iterations);
    so.callbacks.assign(1, &callback);
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    progress.throwIfCancelled();
    result.iterations += static_cast<int>(summary.iterations.size());
    done += iterations;
  }
  if (pixels > 0) {
    const std::vector<double> g = pixelValues();
    map = fitGrayMap(g, pixelTarget, options.grayMapBins, options.grayMapRidge);
    result.imageLossAfter = grayMapImageLoss(map, g, pixelTarget);
    result.grayMap = map;
  }

  layout.rates.resize(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) layout.rates[k] = static_cast<float>(std::exp(s[k]));
  result.rates = layout;
  result.lossAfter = isoContourLoss(contours, GrowthField(axis, ringWidthMm, layout), 1.0);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace kerf

namespace kerf {

GrowthRates remapRingsToWholeYears(const GrowthRates& rates, float ringWidthMm,
                                   const std::vector<double>& ringLevelsYears, int radii) {
  if (ringLevelsYears.size() < 2) throw InputError("at least two ring levels are needed to place the rings");
  std::vector<double> a = ringLevelsYears;
  std::sort(a.begin(), a.end());
  std::vector<double> gaps;
  for (std::size_t i = 1; i < a.size(); ++i) gaps.push_back(a[i] - a[i - 1]);
  const double gap = std::max(1e-6, lowerMedian(gaps));
  const double k0 = std::max(1.0, std::round(a[0] / gap));
  std::vector<double> targets;
  for (std::size_t i = 0; i < a.size(); ++i) targets.push_back(k0 + static_cast<double>(i));
  return remapRingLevels(rates, ringWidthMm, a, targets, radii);
}

GrowthRates remapRingLevels(const GrowthRates& rates, float ringWidthMm, const std::vector<double>& levels,
                            const std::vector<double>& targets, int radii) {
  if (levels.size() < 2 || levels.size() != targets.size())
    throw InputError("at least two ring levels (and as many targets) are needed to place the rings");
  // phi: knots (0, 0), (levels_i, targets_i), kept where both increase; beyond the last knot the
  // median slope of the knots.
  std::vector<double> x{0.0}, y{0.0}, slopes;
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (levels[i] > x.back() + 1e-9 && targets[i] > y.back() + 1e-9) {
      if (x.size() > 1) slopes.push_back((targets[i] - y.back()) / (levels[i] - x.back()));
      x.push_back(levels[i]), y.push_back(targets[i]);
    }
  if (x.size() < 3) throw InputError("the ring levels do not increase with their years");
  const double gap = 1.0 / std::max(1e-6, lowerMedian(slopes));
  auto phi = [&](double g) {
    if (g >= x.back()) return y.back() + (g - x.back()) / gap;
    if (g <= 0) return g * (y[1] / x[1]);
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), g) - x.begin());
    const double t = (g - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + t * (y[i] - y[i - 1]);
  };
  const GrowthField old(PithAxis{}, ringWidthMm, rates);  // only the radial tables are used
  GrowthRates out = rates;
  out.radii = radii;
  out.rates.assign(static_cast<std::size_t>(rates.heights) * rates.azimuths * radii, 1.0f);
  const int nrOld = rates.radii;
  const double stepOld = (rates.radiusMax - rates.radiusMin) / nrOld;
  const double step = (rates.radiusMax - rates.radiusMin) / radii;
  const std::vector<float>& table = old.cumulative();
  for (int h = 0; h < rates.heights; ++h)
    for (int az = 0; az < rates.azimuths; ++az) {
      const float* column = &table[(static_cast<std::size_t>(h) * rates.azimuths + az) * (nrOld + 1)];
      auto gOld = [&](double r) {
        const double f = std::clamp((r - rates.radiusMin) / stepOld, 0.0, static_cast<double>(nrOld));
        const int i = std::min(static_cast<int>(f), nrOld - 1);
        return column[i] + (f - i) * (column[i + 1] - column[i]);
      };
      // Node 0 is tied to the first cell's rate (G(radiusMin) = radiusMin * R_0 / w).
      double current;
      double r0;
      const double target0 = phi(gOld(rates.radiusMin));
      if (rates.radiusMin > 0) {
        r0 = std::max(1e-4, target0 * ringWidthMm / rates.radiusMin);
        current = rates.radiusMin * r0 / ringWidthMm;
      } else {
        r0 = std::max(1e-4, (phi(gOld(step)) - target0) * ringWidthMm / step);
        current = 0;
      }
      out.at(h, az, 0) = static_cast<float>(r0);
      current += step * r0 / ringWidthMm;
      for (int j = 1; j < radii; ++j) {
        const double target = phi(gOld(rates.radiusMin + (j + 1) * step));
        const double rate = std::max(1e-4, (target - current) * ringWidthMm / step);
        out.at(h, az, j) = static_cast<float>(rate);
        current += step * rate / ringWidthMm;
      }
    }
  return out;
}

}  // namespace kerf
