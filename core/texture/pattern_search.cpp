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
    if (bestTrial == trials.size()) {
      endSweep();
      continue;
    }
    std::vector<double> chosen = trials[bestTrial];
    double chosenValue = bestValue;
    if (improvedCount > 1) {  // all improving moves at once: usually better, as the features interact weakly
      const double combined = objective({next})[0];
      ++result.evaluations;
      if (combined < chosenValue) chosen = next, chosenValue = combined;
    }
    result.x = chosen;
    result.value = chosenValue;
    if (onImprovement) onImprovement(result.x, result.value);
    endSweep();
  }
  return result;
}

}  // namespace kerf
