// The texture search's compass search (texture/pattern_search.hpp) on functions whose minimum is known:
// it finds the minimum of a bowl, settles at once the coordinates the function does not see (the fast
// search of issue 16 item 6), and without that tolerance spends evaluations on them. The fast search's
// round trip on a synthetic block is core.TextureInference.RecoversKnownDetailOfASyntheticBlock.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "texture/pattern_search.hpp"

using namespace kerf;

namespace {

// A bowl in x0 and x1 with its minimum at (0.3, 0.7); x2..x5 change nothing.
double bowl(const std::vector<double>& x) {
  return 1.0 + 4.0 * (x[0] - 0.3) * (x[0] - 0.3) + (x[1] - 0.7) * (x[1] - 0.7);
}

PatternSearchResult search(const PatternSearchOptions& options) {
  const std::vector<double> x0(6, 0.5);
  const BatchObjective objective = [](const std::vector<std::vector<double>>& points) {
    std::vector<double> values;
    for (const auto& p : points) values.push_back(bowl(p));
    return values;
  };
  return patternSearch(x0, bowl(x0), objective, options);
}

}  // namespace

TEST(PatternSearch, FindsTheMinimumAndSettlesWhatTheLossDoesNotSee) {
  PatternSearchOptions options;
  options.maxSweeps = 8;
  options.flatTolerance = 0.003;
  const PatternSearchResult fast = search(options);
  EXPECT_NEAR(fast.x[0], 0.3, 1.0 / 32);
  EXPECT_NEAR(fast.x[1], 0.7, 1.0 / 32);
  for (int i = 2; i < 6; ++i) EXPECT_EQ(fast.x[i], 0.5) << i;
  // The four flat coordinates are tried in the first sweep only: 12 trials, then at most 2 x 2 + 1.
  ASSERT_GE(fast.sweepEvaluations.size(), 2u);
  EXPECT_EQ(fast.sweepEvaluations[0], 12 + 1);  // and the combined move of x0 and x1
  for (std::size_t s = 1; s < fast.sweepEvaluations.size(); ++s) EXPECT_LE(fast.sweepEvaluations[s], 5) << s;

  options.flatTolerance = 0;  // the search before: every coordinate halves its step until it is settled
  const PatternSearchResult full = search(options);
  EXPECT_NEAR(full.x[0], 0.3, 1.0 / 32);
  EXPECT_NEAR(full.x[1], 0.7, 1.0 / 32);
  EXPECT_GT(full.evaluations, fast.evaluations + 20);
  // Near the minimum x0 and x1 become flat too (their trials within 0.3 % of the loss): the fast search
  // stops there, within that tolerance of where the full one ends.
  EXPECT_LE(full.value, fast.value);
  EXPECT_NEAR(fast.value, full.value, 0.003 * full.value);
}
