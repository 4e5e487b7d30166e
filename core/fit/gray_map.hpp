#pragma once
// The grey map M of Mokume Sec. 5.2.3 (Eq. 5-6): a piecewise-linear 1D map from growth-field values to
// ring-localization grey, so that M(G(p)) renders the ring-localization image of the faces. Bright runs of
// M mark where the rings are; their centres are the ring iso-values A (MOKUME_CONVENTIONS.md D).
//
// As the authors: the bar is a + M over `bins` entries spanning [gMin, gMax] (a = the mean target grey),
// evaluated by linear interpolation and constant beyond the ends, with a ridge mean(M^2) towards a.
// Kerf solves for M in closed form for a fixed field (a tridiagonal least-squares problem: each sample
// touches two neighbouring entries) instead of taking gradient steps, so M is always the best map for the
// current field. Deviation, on purpose: the authors render with t / 126 and read the peaks with t / 128
// (up to ~0.2 ring apart); Kerf uses one mapping for both.
#include <vector>

namespace kerf {

struct GrayMap {
  double gMin = 0, gMax = 1;  // field values of the first and last entry
  std::vector<double> bar;    // grey (0..1) at evenly spaced field values

  double value(double g) const;  // M(g)
  double slope(double g) const;  // dM/dg (0 beyond the ends)
  // Centres of the runs of entries at or above the bar's mean (MOKUME_CONVENTIONS.md D), in field units,
  // increasing: the ring iso-values A. Unlike the authors, runs closer than half the median spacing are
  // merged (one ring whose run dipped below the mean for an entry).
  std::vector<double> peakCentres() const;
};

// The least-squares map for samples (field value g_i, target grey t_i):
// minimise mean_i (M(g_i) - t_i)^2 + ridge * mean_k (bar_k - a)^2, a = mean_i t_i.
// The range is [min g, max g] of the samples. Needs at least two distinct values of g.
GrayMap fitGrayMap(const std::vector<double>& g, const std::vector<double>& target, int bins = 128,
                   double ridge = 1e-3);

// mean_i |M(g_i) - t_i|: the image loss of Eq. 5 on these samples.
double grayMapImageLoss(const GrayMap& map, const std::vector<double>& g, const std::vector<double>& target);

}  // namespace kerf
