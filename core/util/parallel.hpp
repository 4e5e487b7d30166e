#pragma once
// Row-parallel loops for the renderers: OpenCV's thread pool (cv::parallel_for_), cancellable and
// reporting progress. cv::setNumThreads() decides the thread count (kerf-cli --threads, benchmarks).
#include <functional>

#include "util/progress.hpp"

namespace kerf {

// Calls body(row) for every row in [0, rows), spread over threads. Stops early (throws Cancelled)
// when progress.stop is requested; reports the fraction of rows done.
void parallelRows(int rows, const std::function<void(int row)>& body, const Progress& progress = {});

// Calls body(task) for every task in [0, tasks), each a stripe of its own: for a few long tasks, which
// parallelRows would group. Loops inside a task run serially on its thread (OpenCV does not nest), so
// results do not change. No progress; an exception from body leaves it (OpenCV rewraps it): catch inside.
void parallelTasks(int tasks, const std::function<void(int task)>& body);

// Sets the number of worker threads (0 = all cores).
void setWorkerThreads(int threads);
int workerThreads();

}  // namespace kerf
