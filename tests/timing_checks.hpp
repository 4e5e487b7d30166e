#pragma once
// Latency limits (how many ms a build, a cancel or an event-loop stall may take) are measurements of the
// machine as much as of Kerf. They are checked only in the ctest runs labelled `timing`, which set
// KERF_TIMING_CHECKS=1 and which scripts/test.sh runs alone after the rest; everywhere else a test checks
// behaviour, so a busy machine cannot fail it (issue 20).
#include <QtGlobal>

namespace kerf::testing {

inline bool timingChecks() {
  return qEnvironmentVariableIsSet("KERF_TIMING_CHECKS");
}

}  // namespace kerf::testing
