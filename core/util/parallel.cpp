#include "util/parallel.hpp"

#include <atomic>
#include <opencv2/core/utility.hpp>

namespace kerf {

void parallelRows(int rows, const std::function<void(int)>& body, const Progress& progress) {
  std::atomic<int> done{0};
  std::atomic<bool> cancelled{false};
  // Small stripes keep the threads balanced although rows cost different amounts (pores, rays).
  cv::parallel_for_(
      cv::Range(0, rows),
      [&](const cv::Range& range) {
        for (int row = range.start; row < range.end; ++row) {
          if (progress.stop.stop_requested()) {
            cancelled = true;
            return;
          }
          body(row);
          const int finished = ++done;
          if (progress.report && (finished % 16 == 0 || finished == rows)) {
            progress.report(static_cast<double>(finished) / rows);
          }
        }
      },
      rows / 4.0 + 1);
  if (cancelled) throw Cancelled();
}

void parallelTasks(int tasks, const std::function<void(int)>& body) {
  cv::parallel_for_(
      cv::Range(0, tasks),
      [&](const cv::Range& range) {
        for (int task = range.start; task < range.end; ++task) body(task);
      },
      tasks);
}

void setWorkerThreads(int threads) {
  cv::setNumThreads(threads <= 0 ? -1 : threads);
}

int workerThreads() {
  return cv::getNumThreads();
}

}  // namespace kerf
