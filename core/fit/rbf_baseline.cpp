#include "fit/rbf_baseline.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <glm/geometric.hpp>
#include <set>

#include "util/error.hpp"

namespace kerf {

RbfGrowthField RbfGrowthField::fit(const IsoContours& contours, int maxCentres, double smoothing,
                                   const Progress& progress) {
  std::vector<glm::dvec3> points;
  std::vector<double> years;
  std::set<int> distinct;
  for (int c = 0; c < contours.count(); ++c) {
    if (static_cast<std::size_t>(c) >= contours.year.size() || !contours.year[c]) continue;
    distinct.insert(*contours.year[c]);
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i) {
      points.push_back(glm::dvec3(contours.points[i]));
      years.push_back(*contours.year[c]);
    }
  }
  if (points.size() < 4 || distinct.size() < 2)
    throw InputError("the RBF baseline needs numbered ring traces of at least two different years");
  // Evenly subsampled centres.
  const std::size_t stride = std::max<std::size_t>(1, (points.size() + maxCentres - 1) / maxCentres);
  RbfGrowthField f;
  std::vector<double> g;
  for (std::size_t i = stride / 2; i < points.size(); i += stride) {
    f.centres_.push_back(points[i]);
    g.push_back(years[i]);
  }
  const int n = static_cast<int>(f.centres_.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 4, n + 4);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 4);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double r = glm::length(f.centres_[i] - f.centres_[j]);
      a(i, j) = r * r * r;
    }
    a(i, i) += smoothing;
    const glm::dvec3& p = f.centres_[i];
    a(i, n) = a(n, i) = 1.0;
    a(i, n + 1) = a(n + 1, i) = p.x;
    a(i, n + 2) = a(n + 2, i) = p.y;
    a(i, n + 3) = a(n + 3, i) = p.z;
    b(i) = g[i];
  }
  progress.throwIfCancelled();
  const Eigen::VectorXd x = a.partialPivLu().solve(b);
  if (!x.allFinite()) throw InputError("the RBF baseline system is singular (all traces on one line?)");
  f.weights_.assign(x.data(), x.data() + n);
  for (int k = 0; k < 4; ++k) f.affine_[k] = x(n + k);
  return f;
}

double RbfGrowthField::evaluate(glm::vec3 p) const {
  const glm::dvec3 q(p);
  double g = affine_[0] + affine_[1] * q.x + affine_[2] * q.y + affine_[3] * q.z;
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    const double r = glm::length(q - centres_[i]);
    g += weights_[i] * r * r * r;
  }
  return g;
}

}  // namespace kerf
