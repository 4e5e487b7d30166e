#pragma once
// A straight, round test log and straight knots in it, shared by the knot tests (test_knot_field.cpp,
// test_knot_checks.cpp).
#include <limits>

#include "field/log_model.hpp"

namespace kerf::testing {

// A straight, round log: pith at (0, 0), radius 100 mm, 1000 mm long.
inline LogModel roundLog() {
  LogModel log;
  log.stem.heightStep = 10.0f;
  log.stem.azimuths = 36;
  log.stem.pith.assign(101, glm::vec2(0.0f));
  log.stem.radii.assign(101 * 36, 100.0f);
  return log;
}

// A horizontal knot along azimuth `azimuth` at height z (mm), dead from `death` mm on.
inline Knot straightKnot(float z, float azimuth, float death = std::numeric_limits<float>::infinity()) {
  Knot k;
  k.distanceStep = 10.0f;
  k.heights.assign(12, z);
  k.azimuths.assign(12, azimuth);
  k.deathDistance = death;
  return k;
}

}  // namespace kerf::testing
