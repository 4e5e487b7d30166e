#pragma once
// Wall-clock timing and peak memory, for `kerf-cli --stats` and benchmarks.
#include <chrono>
#include <cstddef>

namespace kerf {

// Peak resident set size of this process so far, in bytes (getrusage).
std::size_t peakResidentBytes();

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace kerf
