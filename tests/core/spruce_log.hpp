#pragma once
// The CT-measured spruce log of shared/data (Larsson et al. 2022's "Gran_1"), as the knot tests and the
// GPU parity test use it. KERF_SHARED_DIR comes from the test's CMake target; the log may be absent.
#include <filesystem>
#include <optional>

#include "field/log_model.hpp"
#include "io/log_data_import.hpp"

namespace kerf::testing {

inline std::filesystem::path granFolder() {
  return std::filesystem::path(KERF_SHARED_DIR) / "data" / "logs" / "spruce-gran1";
}

inline bool granAvailable() {
  return std::filesystem::exists(granFolder() / "Gran_1_knots.json");
}

// The log loaded once per test program, or nullptr where shared/data is absent.
inline const LogModel* granLog() {
  static const std::optional<LogModel> log = []() -> std::optional<LogModel> {
    if (!granAvailable()) return std::nullopt;
    return loadLog(granFolder());
  }();
  return log ? &*log : nullptr;
}

// The knot that dies nearest the pith among those that die well inside the log (at least 30 mm out,
// 0.3 m from either end): where the golden image and the parity test look at a dead knot's butterfly.
inline int earlyDeadKnot(const LogModel& log) {
  int best = -1;
  for (int k = 0; k < static_cast<int>(log.knots.size()); ++k) {
    const Knot& knot = log.knots[k];
    if (knot.deathDistance < 30.0f || knot.heights[0] < 300.0f || knot.heights[0] > 3700.0f) continue;
    if (best < 0 || knot.deathDistance < log.knots[best].deathDistance) best = k;
  }
  return best;
}

}  // namespace kerf::testing

// In a GoogleTest body: skip with a clear message where the log is absent.
#define SKIP_WITHOUT_GRAN()                                                          \
  if (!kerf::testing::granAvailable())                                               \
  GTEST_SKIP() << "the spruce log is not available: " << kerf::testing::granFolder() \
               << " (shared/data is absent)"
