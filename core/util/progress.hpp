#pragma once
// How long work reports progress and learns that it should stop. The caller decides the thread; core
// only calls report() (from any worker thread) and checks the stop token.
#include <functional>
#include <stop_token>

#include "util/error.hpp"

namespace kerf {

struct Progress {
  // Fraction done in [0, 1]. May be called from worker threads concurrently; keep it cheap.
  std::function<void(double)> report;
  std::stop_token stop;

  void set(double fraction) const {
    if (report) report(fraction);
  }
  void throwIfCancelled() const {
    if (stop.stop_requested()) throw Cancelled();
  }
  // The stage [from, to] of this work: reports 0..1 of the stage as from..to here; same stop token.
  Progress part(double from, double to) const {
    Progress sub{nullptr, stop};
    if (report) sub.report = [report = report, from, to](double f) { report(from + (to - from) * f); };
    return sub;
  }
};

}  // namespace kerf
