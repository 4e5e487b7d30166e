#pragma once
// Step 2 of the growth-field fit (Mokume Sec. 5.2.3, Eq. 4): the growth rates R (n_h x n_a x n_r) of
// the field around a fixed pith axis, so that the ring contours become iso-contours.
//
// Method:
//  - R = exp(s): rates stay positive, so rings never cross (the paper clamps R < 0 instead).
//  - For a fixed axis Kerf's field is linear in R (GrowthField: cumulative sum along the radius, linear
//    radially, cubic B-spline weights across heights and spokes), so each contour point's value is
//    G(p) = sum_k A_pk R_k with at most 16 columns of coefficients, precomputed once.
//  - Residuals (Ceres, Levenberg-Marquardt, sparse normal Cholesky): per contour point
//    rho(G(p) - level_c) with a free level per contour and a soft-L1 robust loss (scale in years),
//    weighted 1/sqrt(points) (so the data term is a mean); smoothness of s between neighbouring spokes
//    (periodic), heights and radial cells (mean squared difference, weight `smoothness`); and a ridge
//    mean(s^2) (weight `ridge`, as the authors' mean(R^2)) that keeps the rates near 1: the data term alone
//    could shrink every rate to make all differences small. A hard mean(s) = 0 constraint would couple all
//    2048 rates in one dense row and make each sparse Cholesky step ~30x slower. The overall scale is
//    fixed afterwards anyway, when the rings are placed (growth.ring_width).
//  - Defaults (smoothness 5, ridge 1) chosen on CN03: weaker regularisation lowers the iso-contour loss
//    further (0.040 ring spacings at 0.05 / 0.01) but places the rings worse on the faces (image loss up),
//    since nothing but the field's continuity ties a ring's level on one face to its level on the next.
//  - The paper's image term with the grey map M (Eq. 5-6) is not used: the ring iso-values are placed
//    afterwards from the ring-localization images along the fitted field (estimateRingLevels with the
//    fitted field), which plays M's role of placing rings at arbitrary values.
#include <vector>

#include "field/growth_rates.hpp"
#include "field/pith_axis.hpp"
#include "fit/iso_contour_loss.hpp"
#include "geometry/block.hpp"
#include "util/progress.hpp"

namespace kerf {

struct DistortionFitOptions {
  int heights = 8, azimuths = 16, radii = 16;  // Mokume A.2.2
  double smoothness = 5.0;  // weight of the mean squared difference of s between neighbouring cells
  double ridge = 1.0;       // weight of mean(s^2): towards uniform rates
  double robustScaleYears = 0.05;
  int maxFitPoints = 6000;
  int maxIterations = 50;
};

struct DistortionFitResult {
  GrowthRates rates;
  IsoContourLoss lossBefore, lossAfter;  // in years, normalized by 1 year (the ring spacing of the field)
  int iterations = 0;
  double seconds = 0;
};

// Throws InputError without contours, Cancelled on request.
DistortionFitResult fitDistortions(const IsoContours& contours, const Block& block, const PithAxis& axis,
                                   float ringWidthMm, const DistortionFitOptions& options = {},
                                   const Progress& progress = {});

// The linear coefficients of G(p) in the rates (what fitDistortions uses); exposed for tests:
// G(p) = sum over entries of weight * rates[index].
struct RateCoefficient {
  int index;
  double weight;
};
std::vector<RateCoefficient> growthCoefficients(const GrowthRates& layout, const PithAxis& axis,
                                                float ringWidthMm, glm::vec3 p);

// Kerf's field has its rings at whole years (growth.ring_offset + k), the paper's at arbitrary iso-values
// A (the peaks of M). This turns a fitted field with rings at `ringLevelsYears` (increasing, years of the
// field built with ringWidthMm) into one with ring i at whole year k0 + i: G' = phi(G), phi piecewise
// linear through (0, 0), (A_i, k0 + i), continued with the median gap beyond the last ring, applied to
// every column's radial nodes on a finer radial grid (`radii` cells; the field is exact at the nodes, and
// the B-spline blend across spokes/heights commutes with phi only approximately). Rates are kept >= 1e-4.
GrowthRates remapRingsToWholeYears(const GrowthRates& rates, float ringWidthMm,
                                   const std::vector<double>& ringLevelsYears, int radii = 64);

}  // namespace kerf
