#pragma once
// The baseline of the learned-inference paper (Sec. 4, Table 1): naive radial-basis-function
// interpolation of numbered ring traces. G(p) = sum_i w_i |p - c_i|^3 + b0 + b . p (the 3D
// polyharmonic spline with a linear polynomial, which interpolates smoothly without a shape parameter),
// fitted to the trace points (x_k, year_k). It knows nothing about trees: no pith, no monotone radial
// growth, so it is exact on the traces and guesses between them. Kerf offers it to compare against its
// growth-field fit (docs/rings.md).
#include <glm/vec3.hpp>
#include <vector>

#include "fit/iso_contour_loss.hpp"
#include "util/progress.hpp"

namespace kerf {

class RbfGrowthField {
 public:
  // Fits to the numbered contours' points (unnumbered ones are ignored), evenly subsampled to at most
  // maxCentres centres; `smoothing` (years^2 per unit weight) regularises near-duplicate points.
  // Throws InputError with fewer than 4 numbered points or no two different years.
  static RbfGrowthField fit(const IsoContours& contours, int maxCentres = 1000, double smoothing = 1e-4,
                            const Progress& progress = {});

  double evaluate(glm::vec3 p) const;  // the year at p
  int centres() const { return static_cast<int>(centres_.size()); }

 private:
  std::vector<glm::dvec3> centres_;
  std::vector<double> weights_;
  double affine_[4] = {0, 0, 0, 0};  // b0, bx, by, bz
};

}  // namespace kerf
