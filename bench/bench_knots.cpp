// kerf_bench: boards cut from the CT-measured spruce log with all its 108 knots (docs/knots.md,
// docs/performance.md). The log is loaded once, outside the timed loops; every iteration renders the
// default flat-sawn board (a knotty section) at 1200 x 1200 px on the CPU.
//
//   build-k/bench/kerf_bench --benchmark_filter=Knot
//
// Needs ../shared/data/logs/spruce-gran1; the benchmarks report an error and skip when it is absent.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <optional>

#include "field/knot_field.hpp"
#include "io/log_data_import.hpp"
#include "render/board_renderer.hpp"
#include "util/parallel.hpp"

namespace {

const kerf::LogModel* spruceLog() {
  static const std::optional<kerf::LogModel> log = []() -> std::optional<kerf::LogModel> {
    const std::filesystem::path folder =
        std::filesystem::path(KERF_SHARED_DIR) / "data" / "logs" / "spruce-gran1";
    if (!std::filesystem::exists(folder / "Gran_1_knots.json")) return std::nullopt;
    return kerf::loadLog(folder);
  }();
  return log ? &*log : nullptr;
}

// Arg 0: worker threads; Arg 1: 1 = culling (Kerf's renderer), 0 = every knot at every pixel.
void BM_KnotBoard(benchmark::State& state) {
  const kerf::LogModel* log = spruceLog();
  if (!log) {
    state.SkipWithError("shared/data/logs/spruce-gran1 is absent");
    return;
  }
  kerf::setWorkerThreads(static_cast<int>(state.range(0)));
  const kerf::KnotField field(*log, kerf::KnotSettings{});
  const kerf::Board board = kerf::defaultBoard(*log);
  kerf::BoardRenderOptions options;
  options.resolution = 1200;
  options.cull = state.range(1) != 0;
  kerf::BoardRenderStats stats;
  for (auto _ : state) {
    kerf::Image image = kerf::renderBoardFace(field, log->colorMap, board, options, &stats);
    benchmark::DoNotOptimize(image.pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(stats.pixels));
  state.counters["knots_board"] = stats.boardKnots;
  state.counters["knots_tile"] = stats.meanTileKnots;
  kerf::setWorkerThreads(0);
}
BENCHMARK(BM_KnotBoard)
    ->ArgNames({"threads", "cull"})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({2, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One point of the field, testing all 108 knots (the per-pixel cost without culling).
void BM_KnotFieldPoint(benchmark::State& state) {
  const kerf::LogModel* log = spruceLog();
  if (!log) {
    state.SkipWithError("shared/data/logs/spruce-gran1 is absent");
    return;
  }
  const kerf::KnotField field(*log, kerf::KnotSettings{});
  const kerf::Board board = kerf::defaultBoard(*log);
  std::vector<glm::vec3> points;
  for (int i = 0; i < 1024; ++i) {
    points.push_back(board.toLog(glm::vec3(-50.0f + 0.1f * i, 10.0f * std::sin(0.37f * i), 15.0f)));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(field.evaluate(points[i]));
    i = (i + 1) & 1023;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KnotFieldPoint);

}  // namespace
