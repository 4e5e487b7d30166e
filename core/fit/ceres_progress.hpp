#pragma once
// A Ceres iteration callback that reports a solve's progress and stops it when the job is cancelled:
// every Ceres solve in Kerf runs inside a job the user can cancel.
#include <ceres/iteration_callback.h>
#include <algorithm>

#include "util/progress.hpp"

namespace kerf {

class CeresProgress final : public ceres::IterationCallback {
 public:
  // Iteration i of at most `maxIterations` sets progress to from + (to - from) (i + 1) / maxIterations;
  // maxIterations 0 only watches for cancellation.
  explicit CeresProgress(const Progress& progress, int maxIterations = 0, double from = 0.0, double to = 1.0)
      : progress_(progress), max_(maxIterations), from_(from), to_(to) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (max_ > 0) {
      progress_.set(from_ + (to_ - from_) * std::min(1.0, (summary.iteration + 1.0) / max_));
    }
    return progress_.stop.stop_requested() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const Progress& progress_;
  int max_;
  double from_, to_;
};

}  // namespace kerf
