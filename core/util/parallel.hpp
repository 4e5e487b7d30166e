#pragma once
// Row-parallel loops for the renderers: OpenCV's thread pool (cv::parallel_for_), cancellable and
// reporting progress. cv::setNumThreads() decides the thread count (kerf-cli --threads, benchmarks).
#include <functional>

#include "util/progress.hpp"

namespace kerf {

// Calls body(row) for every row in [0, rows), spread over threads. Stops early (throws Cancelled)
// when progress.stop is requested; reports the fraction of rows done.
void parallelRows(int rows, const std::function<void(int row)>& body, const Progress& progress = {});

// Calls body(task) for every task in [0, tasks) at the same time, each on a thread of its own (task 0 on
// the caller's): for a few long tasks that are mostly serial inside. A task's own parallelRows loops use
// the thread pool when it is free and otherwise run serially on the task's thread (OpenCV runs
// concurrent loops one at a time), so a task left alone gets both cores back; results do not depend on
// it. With one worker thread (setWorkerThreads(1)) the tasks run one after the other. The first
// exception a task throws is rethrown once all have ended.
void parallelTasks(int tasks, const std::function<void(int task)>& body);

// Sets the number of worker threads (0 = all cores).
void setWorkerThreads(int threads);
int workerThreads();

}  // namespace kerf
