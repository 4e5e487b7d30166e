#pragma once
// A derivative-free minimiser for the texture inference: a parallel coordinate (compass) search in the
// unit box. The style loss of a procedural texture is not smooth in its parameters (moving a pore size
// moves pores across pixels and cells in and out of existence), so gradients - and hence Ceres - are no
// use; Nelder-Mead needs many serial steps in ~18 dimensions. A compass search (Kolda, Lewis & Torczon
// 2003) tries +-step along every coordinate; all those trials are independent, so they are evaluated as
// one parallel batch. Every coordinate that improved moves, a combined move is tried too, and a
// coordinate's step halves when neither direction helped. Deterministic: no random numbers.
#include <functional>
#include <vector>

#include "util/progress.hpp"

namespace kerf {

struct PatternSearchOptions {
  double initialStep = 0.125;  // in unit coordinates
  double minStep = 1.0 / 64;   // a coordinate whose step fell below is settled
  // With flatTolerance 0.003 (issue 16 item 6): on CN03 227 evaluations for 288 without it, the same
  // appearance scores; --flat-tolerance 0 is the search before, bit for bit. The texture inference runs 4
  // sweeps (TextureInferenceOptions::search).
  int maxSweeps = 8;
  // A coordinate is settled at once when neither of its trials moved the loss by more than this share of
  // it (0: never): halving the step of a parameter the loss does not see (faint rays, a pore size at zero
  // density) would only spend evaluations.
  double flatTolerance = 0.003;
};

// Values of the objective at each point of a batch (the caller evaluates them in parallel).
using BatchObjective = std::function<std::vector<double>(const std::vector<std::vector<double>>& points)>;

struct PatternSearchResult {
  std::vector<double> x;
  double value = 0;
  int evaluations = 0;
  int sweeps = 0;
  std::vector<double> sweepValues;    // the best value after each sweep
  std::vector<int> sweepEvaluations;  // the evaluations of each sweep
};

// Starts at x0 (value f0, already known). onImprovement is called with every new best point.
PatternSearchResult patternSearch(
    std::vector<double> x0, double f0, const BatchObjective& objective,
    const PatternSearchOptions& options = {},
    const std::function<void(const std::vector<double>&, double)>& onImprovement = {},
    const Progress& progress = {});

}  // namespace kerf
