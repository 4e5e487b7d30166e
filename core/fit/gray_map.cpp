#include "fit/gray_map.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace kerf {

namespace {

// Entry index and interpolation weight of g on the bar.
struct Cell {
  int i0;
  double f;
};

Cell cellOf(const GrayMap& m, double g) {
  const int n = static_cast<int>(m.bar.size());
  const double t = std::clamp((g - m.gMin) / (m.gMax - m.gMin), 0.0, 1.0) * (n - 1);
  const int i0 = std::min(static_cast<int>(t), n - 2);
  return {i0, t - i0};
}

}  // namespace

double GrayMap::value(double g) const {
  const Cell c = cellOf(*this, g);
  return (1.0 - c.f) * bar[c.i0] + c.f * bar[c.i0 + 1];
}

double GrayMap::slope(double g) const {
  if (g <= gMin || g >= gMax) return 0.0;
  const Cell c = cellOf(*this, g);
  return (bar[c.i0 + 1] - bar[c.i0]) * (static_cast<double>(bar.size()) - 1) / (gMax - gMin);
}

std::vector<double> GrayMap::peakCentres() const {
  const int n = static_cast<int>(bar.size());
  double mean = 0;
  for (double b : bar) mean += b;
  mean /= n;
  struct Run {
    double centre, mass;
  };
  std::vector<Run> runs;
  const double step = (gMax - gMin) / (n - 1);
  int start = -1;
  double mass = 0;
  for (int i = 0; i <= n; ++i) {
    const bool above = i < n && bar[i] >= mean;
    if (above && start < 0) start = i, mass = 0;
    if (above) mass += bar[i] - mean + 1e-9;
    if (!above && start >= 0) {
      // Entries start..i-1 are bright; the run's centre in entry units is (start + i - 1) / 2.
      runs.push_back({gMin + step * 0.5 * (start + i - 1), mass});
      start = -1;
    }
  }
  // A ring whose bright run dips below the threshold for an entry or two shows as two runs a fraction of
  // a ring apart: merge neighbours closer than half the median spacing (mass-weighted centre).
  while (runs.size() >= 3) {
    std::vector<double> gaps;
    for (std::size_t i = 1; i < runs.size(); ++i) gaps.push_back(runs[i].centre - runs[i - 1].centre);
    std::vector<double> sorted = gaps;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    const auto closest = std::min_element(gaps.begin(), gaps.end());
    if (*closest >= 0.5 * median) break;
    const std::size_t i = static_cast<std::size_t>(closest - gaps.begin());
    Run& a = runs[i];
    const Run& b = runs[i + 1];
    a.centre = (a.centre * a.mass + b.centre * b.mass) / (a.mass + b.mass);
    a.mass += b.mass;
    runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  }
  std::vector<double> centres;
  for (const Run& r : runs) centres.push_back(r.centre);
  return centres;
}

GrayMap fitGrayMap(const std::vector<double>& g, const std::vector<double>& target, int bins, double ridge) {
  if (g.size() != target.size() || bins < 2) throw InputError("grey map: bad samples");
  GrayMap m;
  m.gMin = *std::min_element(g.begin(), g.end());
  m.gMax = *std::max_element(g.begin(), g.end());
  if (g.size() < 2 || !(m.gMax > m.gMin)) throw InputError("grey map: the field is constant on the faces");
  m.bar.assign(bins, 0.0);
  double a = 0;
  for (double t : target) a += t;
  a /= static_cast<double>(target.size());
  // Normal equations of the tridiagonal least-squares problem: diag d, off-diagonal e (i, i + 1), rhs b.
  std::vector<double> d(bins, 0.0), e(bins, 0.0), b(bins, 0.0);
  const double wData = 1.0 / static_cast<double>(g.size()), wRidge = ridge / bins;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = cellOf(m, g[i]);
    const double w0 = 1.0 - c.f, w1 = c.f;
    d[c.i0] += wData * w0 * w0;
    d[c.i0 + 1] += wData * w1 * w1;
    e[c.i0] += wData * w0 * w1;
    b[c.i0] += wData * w0 * target[i];
    b[c.i0 + 1] += wData * w1 * target[i];
  }
  for (int k = 0; k < bins; ++k) d[k] += wRidge, b[k] += wRidge * a;
  // Thomas algorithm (the matrix is symmetric positive definite, so no pivoting is needed).
  std::vector<double> c(bins, 0.0), y(bins, 0.0);
  c[0] = e[0] / d[0];
  y[0] = b[0] / d[0];
  for (int k = 1; k < bins; ++k) {
    const double den = d[k] - e[k - 1] * c[k - 1];
    c[k] = e[k] / den;
    y[k] = (b[k] - e[k - 1] * y[k - 1]) / den;
  }
  m.bar[bins - 1] = y[bins - 1];
  for (int k = bins - 2; k >= 0; --k) m.bar[k] = y[k] - c[k] * m.bar[k + 1];
  return m;
}

double grayMapImageLoss(const GrayMap& map, const std::vector<double>& g, const std::vector<double>& target) {
  double sum = 0;
  for (std::size_t i = 0; i < g.size(); ++i) sum += std::abs(map.value(g[i]) - target[i]);
  return g.empty() ? 0.0 : sum / static_cast<double>(g.size());
}

}  // namespace kerf
