#include "texture/pattern_search.hpp"

#include <algorithm>
#include <cmath>

namespace kerf {

PatternSearchResult patternSearch(
    std::vector<double> x0, double f0, const BatchObjective& objective, const PatternSearchOptions& options,
    const std::function<void(const std::vector<double>&, double)>& onImprovement, const Progress& progress) {
  PatternSearchResult result{std::move(x0), f0, 0, 0, {}, {}};
  const std::size_t n = result.x.size();
  std::vector<double> step(n, options.initialStep);
  for (int sweep = 0; sweep < options.maxSweeps; ++sweep) {
    progress.throwIfCancelled();
    // Trial points: +-step along every unsettled coordinate, clamped to the box.
    std::vector<std::vector<double>> trials;
    std::vector<std::pair<std::size_t, double>> moves;  // coordinate, new value
    for (std::size_t i = 0; i < n; ++i) {
      if (step[i] < options.minStep) continue;
      for (double sign : {-1.0, 1.0}) {
        const double v = std::clamp(result.x[i] + sign * step[i], 0.0, 1.0);
        if (std::abs(v - result.x[i]) < 1e-12) continue;
        trials.push_back(result.x);
        trials.back()[i] = v;
        moves.emplace_back(i, v);
      }
    }
    if (trials.empty()) break;
    const int evaluationsBefore = result.evaluations;
    const auto endSweep = [&] {
      result.sweepValues.push_back(result.value);
      result.sweepEvaluations.push_back(result.evaluations - evaluationsBefore);
      progress.set(static_cast<double>(sweep + 1) / options.maxSweeps);
    };
    const std::vector<double> values = objective(trials);
    result.evaluations += static_cast<int>(trials.size());
    result.sweeps = sweep + 1;

    // The best move of each coordinate that improved on the current point.
    std::vector<double> bestOf(n, result.value);
    std::vector<double> moveOf(n, 0.0);
    std::vector<bool> improved(n, false);
    std::vector<double> change(n, 0.0);  // the largest |trial - current| of each coordinate
    for (std::size_t t = 0; t < trials.size(); ++t)
      change[moves[t].first] = std::max(change[moves[t].first], std::abs(values[t] - result.value));
    std::size_t bestTrial = trials.size();
    double bestValue = result.value;
    for (std::size_t t = 0; t < trials.size(); ++t) {
      const auto [i, v] = moves[t];
      if (values[t] < bestOf[i]) bestOf[i] = values[t], moveOf[i] = v, improved[i] = true;
      if (values[t] < bestValue) bestValue = values[t], bestTrial = t;
    }
    std::vector<double> next = result.x;
    int improvedCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (improved[i]) {
        next[i] = moveOf[i];
        ++improvedCount;
      } else if (options.flatTolerance > 0 && step[i] >= options.minStep &&
                 change[i] <= options.flatTolerance * std::abs(result.value)) {
        step[i] = 0;  // flat: settled
      } else {
        step[i] *= 0.5;
      }
    }
    // The parabolic point: each coordinate at its parabola's minimum through (x - a, f-), (x, f), (x + b,
    // f+).
    std::vector<double> vertex = result.x;
    bool hasVertex = false;
    if (options.parabolic) {
      std::vector<double> below(n, -1), above(n, -1), fBelow(n, 0), fAbove(n, 0);
      for (std::size_t t = 0; t < trials.size(); ++t) {
        const auto [i, v] = moves[t];
        if (v < result.x[i])
          below[i] = result.x[i] - v, fBelow[i] = values[t];
        else
          above[i] = v - result.x[i], fAbove[i] = values[t];
      }
      for (std::size_t i = 0; i < n; ++i) {
        if (below[i] <= 0 || above[i] <= 0) continue;
        const double a = below[i], b = above[i], f0 = result.value;
        const double slopeUp = (fAbove[i] - f0) / b, slopeDown = (f0 - fBelow[i]) / a;
        const double curvature = (slopeUp - slopeDown) / (0.5 * (a + b));
        if (!(curvature > 0)) continue;
        // f(x + d) ~ f0 + g d + curvature d^2 / 2, g the slope at x.
        const double g = (slopeUp * a + slopeDown * b) / (a + b);
        const double d = std::clamp(-g / curvature, -2.0 * a, 2.0 * b);
        vertex[i] = std::clamp(result.x[i] + d, 0.0, 1.0);
        hasVertex = hasVertex || std::abs(vertex[i] - result.x[i]) > 1e-12;
      }
    }
    if (bestTrial == trials.size() && !hasVertex) {
      endSweep();
      continue;
    }
    std::vector<double> chosen = bestTrial < trials.size() ? trials[bestTrial] : result.x;
    double chosenValue = bestValue;
    // All improving moves at once (usually better, as the features interact weakly), and the parabolic
    // point: evaluated together.
    std::vector<std::vector<double>> extra;
    if (improvedCount > 1) extra.push_back(next);
    if (hasVertex && vertex != next && vertex != chosen) extra.push_back(vertex);
    if (!extra.empty()) {
      const std::vector<double> extraValues = objective(extra);
      result.evaluations += static_cast<int>(extra.size());
      for (std::size_t e = 0; e < extra.size(); ++e)
        if (extraValues[e] < chosenValue) chosen = extra[e], chosenValue = extraValues[e];
    }
    if (chosenValue >= result.value) {
      endSweep();
      continue;
    }
    result.x = chosen;
    result.value = chosenValue;
    if (onImprovement) onImprovement(result.x, result.value);
    endSweep();
  }
  return result;
}

}  // namespace kerf
