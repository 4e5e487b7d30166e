#pragma once
// Checks that a fit changed only the parameters the schema says it may change (the `fits` column of
// params/wood_parameters.def), so that column stays true as fits evolve.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "params/parameter_schema.hpp"

namespace kerf::test {

// Every parameter that differs between `before` and `after` must be marked fitted by `fit`; returns how
// many differ (a check that asserts on nothing changed would prove nothing).
inline int expectOnlyFittedParametersChanged(const WoodParameters& before, const WoodParameters& after,
                                             FitBy fit) {
  const auto schema = parameterSchema();
  int changed = 0;
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const auto a = before.components(i), b = after.components(i);
    if (std::equal(a.begin(), a.end(), b.begin(), b.end())) continue;
    ++changed;
    EXPECT_TRUE(schema[i].fittedBy(fit))
        << "the " << fitName(fit) << " fit changed " << schema[i].id << ", which the schema does not mark";
  }
  return changed;
}

}  // namespace kerf::test
