#include <cstdio>
#include <memory>

#include "command.hpp"
#include "util/parallel.hpp"
#include "util/resource_usage.hpp"

namespace kerf::cli {
Progress Context::progress() const {
  if (quiet) return {};
  auto last = std::make_shared<int>(-1);
  return {[last](double f) {
            const int percent = static_cast<int>(f * 100.0);
            if (percent / 10 != *last / 10) {
              *last = percent;
              std::fprintf(stderr, "\r%3d%%", percent);
              if (percent >= 100) std::fprintf(stderr, "\n");
            }
          },
          {}};
}

void Context::printStats(const std::string& command) const {
  if (!stats) return;
  const double s = stopwatch.seconds();
  std::fprintf(
      stderr,
      "stats: command=%s wall=%.3f s threads=%d samples=%zu throughput=%.3g samples/s peak_rss=%.1f MiB\n",
      command.c_str(), s, workerThreads(), samples, s > 0 ? samples / s : 0.0,
      peakResidentBytes() / (1024.0 * 1024.0));
}

}  // namespace kerf::cli
