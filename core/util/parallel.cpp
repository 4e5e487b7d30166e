#include "util/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <opencv2/core/utility.hpp>
#include <thread>
#include <vector>

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
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(tasks, 0)));
  const auto run = [&](int task) {
    try {
      body(task);
    } catch (...) {
      errors[task] = std::current_exception();
    }
  };
  if (workerThreads() <= 1) {
    for (int task = 0; task < tasks; ++task) run(task);
  } else {
    std::vector<std::thread> threads;
    for (int task = 1; task < tasks; ++task) threads.emplace_back(run, task);
    if (tasks > 0) run(0);
    for (std::thread& t : threads) t.join();
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

void setWorkerThreads(int threads) {
  cv::setNumThreads(threads <= 0 ? -1 : threads);
}

int workerThreads() {
  return cv::getNumThreads();
}

}  // namespace kerf
