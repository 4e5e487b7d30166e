#pragma once
// Step 2 of the growth-field fit (Mokume Sec. 5.2.3, Eq. 4): the growth rates R (n_h x n_a x n_r) of
// the field around a fixed pith axis, so that the ring contours become iso-contours.
//
// Method:
//  - R = exp(s): rates stay positive, so rings never cross (the paper clamps R < 0 instead).
//  - For a fixed axis Kerf's field is linear in R (GrowthField: cumulative sum along the radius, linear
//    radially, cubic B-spline weights across heights and spokes), so each contour point's value is
//    G(p) = sum_k A_pk R_k with at most 16 columns of coefficients, precomputed once.
//  - Residuals (Ceres, Levenberg-Marquardt with inexact CGNR steps): per contour point
//    rho(G(p) - level_c) with a free level per contour (numbered traces too: their years place the rings
//    afterwards, see growth_field_fit.hpp) and a soft-L1 robust loss (scale in years),
//    weighted 1/sqrt(points) (so the data term is a mean); smoothness of s between neighbouring spokes
//    (periodic), heights and radial cells (mean squared difference, weight `smoothness`); and a ridge
//    mean(s^2) (weight `ridge`, as the authors' mean(R^2)) that keeps the rates near 1: the data term alone
//    could shrink every rate to make all differences small. A hard mean(s) = 0 constraint would couple all
//    2048 rates in one dense row and make each sparse Cholesky step ~30x slower. The overall scale is
//    fixed afterwards anyway, when the rings are placed (growth.ring_width).
//  - The grid spans the block as seen from the axis (GrowthRates::Azimuths::Block): with the pith far
//    outside the block its 16 spokes cover the few degrees the block fills, as in the authors' code (B.3);
//    around the full circle the whole block would fall between two spokes and could not bend.
//  - Image term (Eq. 5-6), when ring-localization images are given: after a first solve on the contours
//    alone, the grey map M (fit/gray_map.hpp) is fitted in closed form to the current field and held
//    fixed while LM moves the rates with the residuals imageWeight * mean_px (M(G(p)) - ARL(p))^2 added
//    (squared, not the authors' L1: LM needs least squares; the soft-L1 contour term stays robust);
//    then M is refitted and the rates solved again (imageRounds times). The ring iso-values A are the
//    centres of M's bright runs (MOKUME_CONVENTIONS.md D) after the last round.
//  - Defaults (smoothness 1, ridge 0.2, image weight 0.05) chosen on CN03 and the synthetic distorted
//    block of tests/core/test_pith_fit.cpp: weaker regularisation lowers CN03's iso-contour loss further
//    but buys little on the synthetic hidden cut (docs/rings.md has the numbers).
#include <array>
#include <optional>
#include <vector>

#include "field/growth_rates.hpp"
#include "field/pith_axis.hpp"
#include "fit/gray_map.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/iso_contours.hpp"
#include "geometry/block.hpp"
#include "util/progress.hpp"

namespace kerf {

struct DistortionFitOptions {
  int heights = 8, azimuths = 16, radii = 16;  // Mokume A.2.2
  double smoothness = 1.0;  // weight of the mean squared difference of s between neighbouring cells
  double ridge = 0.2;       // weight of mean(s^2): towards uniform rates
  double robustScaleYears = 0.05;
  int maxFitPoints = 6000;
  int maxIterations = 20;  // per solve (CN03 converges in 11; the cost is flat after ~15)
  // Image term (used when ring images are passed): weight of mean (M(G) - ARL)^2, every imageStride-th
  // pixel of each face, imageRounds refits of M after the contour-only solve.
  double imageWeight = 0.05;
  int imageStride = 12;
  int imageRounds = 1;
  int imageIterations = 8;  // per round with the image term (M moves between rounds)
  int grayMapBins = 128;    // as the authors
  double grayMapRidge = 1e-3;
};

struct DistortionFitResult {
  GrowthRates rates;
  IsoContourLoss lossBefore, lossAfter;  // in years, normalized by 1 year (the ring spacing of the field)
  // With ring images: M fitted to the result (field values in years of ringWidthMm), and the image loss
  // mean |M(G) - ARL| on the sampled pixels after the contour-only solve and at the end.
  std::optional<GrayMap> grayMap;
  double imageLossBefore = 0, imageLossAfter = 0;
  int iterations = 0;
  double seconds = 0;
};

// Throws InputError without contours, Cancelled on request. ringImages (A..F, empty faces skipped)
// switch on the image term.
DistortionFitResult fitDistortions(const IsoContours& contours, const Block& block, const PithAxis& axis,
                                   float ringWidthMm, const DistortionFitOptions& options = {},
                                   const Progress& progress = {},
                                   const std::array<GrayImage8, 6>* ringImages = nullptr);

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
// The same with explicit targets: level_i (increasing) goes to targets_i (increasing; pairs that do
// not increase are skipped). Numbered traces use it to put ring y exactly at G = y - a.
GrowthRates remapRingLevels(const GrowthRates& rates, float ringWidthMm, const std::vector<double>& levels,
                            const std::vector<double>& targets, int radii = 64);

}  // namespace kerf
