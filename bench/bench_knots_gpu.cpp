// kerf_bench_knots_gpu: the GLSL knot model (gpu/gpu_board_renderer.*) on the default flat-sawn
// board of the CT-measured spruce log (all 108 knots, culled per board and per tile on the CPU), 1200 x
// 1200 px, offscreen. Prints the median over the runs of the whole render (culling, upload, draw, readback
// into an RGB float image) and of each phase; the program is compiled once, before the timed runs.
//
//   xvfb-run -a build-k/bench/kerf_bench_knots_gpu [runs=9] [--no-cull]
//
// Needs ../shared/data/logs/spruce-gran1 and an OpenGL 3.3 core context (docs/performance.md).
#include <QGuiApplication>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>
#include <vector>

#include "gpu/gpu_board_renderer.hpp"
#include "gpu/offscreen_gl_context.hpp"
#include "io/log_data_import.hpp"
#include "util/resource_usage.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 9;
  bool cull = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-cull") == 0)
      cull = false;
    else
      runs = std::max(1, std::atoi(argv[i]));
  }
  const std::filesystem::path folder =
      std::filesystem::path(KERF_SHARED_DIR) / "data" / "logs" / "spruce-gran1";
  if (!std::filesystem::exists(folder / "Gran_1_knots.json")) {
    std::fprintf(stderr, "%s is absent\n", folder.c_str());
    return 1;
  }
  QGuiApplication app(argc, argv);
  kerf::OffscreenGlContext context;
  if (const std::string error = context.makeCurrent(); !error.empty()) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const kerf::LogModel log = kerf::loadLog(folder);
  const kerf::KnotField field(log, kerf::KnotSettings{});
  const kerf::Board board = kerf::defaultBoard(log);
  kerf::BoardRenderOptions options;
  options.resolution = 1200;
  options.cull = cull;

  const kerf::Stopwatch compileWatch;
  kerf::GpuBoardRenderer renderer;
  const double compile = compileWatch.seconds();
  kerf::BoardRenderStats stats;
  const kerf::Stopwatch firstWatch;
  renderer.render(field, log.colorMap, board, options, &stats);  // warm-up (llvmpipe JITs on first draw)
  const double first = firstWatch.seconds();
  std::vector<double> total, cullT, upload, draw, readback;
  for (int r = 0; r < runs; ++r) {
    kerf::GpuBoardTimings t;
    const kerf::Stopwatch watch;
    const kerf::Image image = renderer.render(field, log.colorMap, board, options, &stats, &t);
    total.push_back(watch.seconds());
    cullT.push_back(t.cull), upload.push_back(t.upload), draw.push_back(t.draw),
        readback.push_back(t.readback);
    if (image.width != 1200) return 1;
  }
  std::printf("renderer: %s\n", context.renderer().c_str());
  std::printf("board %s, %zu px, knots: log=%zu board=%d per-tile=%.2f per-pixel-in-reach=%.2f%s\n",
              kerf::formatBoard(board).c_str(), stats.pixels, log.knots.size(), stats.boardKnots,
              stats.meanTileKnots, stats.meanKnotsInReach, cull ? "" : " (no culling)");
  std::printf(
      "compile+link %.3f s, first render (shader JIT) %.3f s; median of %d runs: total %.3f s = cull %.3f + "
      "upload %.3f + draw %.3f "
      "+ readback %.3f (min total %.3f, max %.3f); hardware threads %u\n",
      compile, first, runs, median(total), median(cullT), median(upload), median(draw), median(readback),
      *std::min_element(total.begin(), total.end()), *std::max_element(total.begin(), total.end()),
      std::thread::hardware_concurrency());
  return 0;
}
