// kerf_bench: throughput of the CPU wood model on the demo block (docs/performance.md).
//
//   build-bench/bench/kerf_bench --benchmark_format=console
//
// The WoodModel is built once, outside every timed loop. Point benchmarks cycle through a fixed,
// precomputed spread of points inside the 40 mm block; image benchmarks render with samples = 1.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "demo/demo_block.hpp"
#include "geometry/cut_plane.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "util/parallel.hpp"

namespace {

constexpr std::size_t kPointCount = 4096;  // a power of two: the loops index with a mask

const kerf::WoodModel& demoModel() {
  static const kerf::WoodModel model(kerf::demoProject());
  return model;
}

// Uniformly spread points inside the block (fixed seed, so every run sees the same points).
const std::vector<glm::vec3>& samplePoints() {
  static const std::vector<glm::vec3> points = [] {
    const glm::vec3 half = demoModel().block().halfSize();
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> out(kPointCount);
    for (glm::vec3& p : out) p = glm::vec3(unit(rng), unit(rng), unit(rng)) * half;
    return out;
  }();
  return points;
}

// The growth field G alone (cylindrical coordinates + table lookup), no distortion, no texture.
void BM_GrowthField(benchmark::State& state) {
  const kerf::GrowthField& field = demoModel().field();
  const std::vector<glm::vec3>& points = samplePoints();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(field.evaluate(points[i]));
    i = (i + 1) & (kPointCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GrowthField);

// The growth time at the distorted point (what export-volume --quantity growth samples).
void BM_MaterialYear(benchmark::State& state) {
  const kerf::WoodMaterial& material = demoModel().material();
  const std::vector<glm::vec3>& points = samplePoints();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(material.year(points[i]));
    i = (i + 1) & (kPointCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MaterialYear);

// The full texture (colour) at a point; Arg(1) also computes the fibre direction.
void BM_WoodEvaluate(benchmark::State& state) {
  const kerf::WoodModel& model = demoModel();
  const std::vector<glm::vec3>& points = samplePoints();
  const bool withFiber = state.range(0) != 0;
  std::size_t i = 0;
  for (auto _ : state) {
    kerf::WoodSample sample = model.evaluate(points[i], -1, withFiber);
    benchmark::DoNotOptimize(sample);
    i = (i + 1) & (kPointCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(withFiber ? "colour + fibre direction" : "colour");
}
BENCHMARK(BM_WoodEvaluate)->ArgName("fiber")->Arg(0)->Arg(1);

// A slanted cut through the block centre (normal 1,1,1), about 1024 x 1024 pixels in all, samples 1.
// Arg: worker threads (0 = all cores). Items are image pixels, inside the block or not.
void BM_RenderCut(benchmark::State& state) {
  const kerf::WoodModel& model = demoModel();
  const kerf::CutPlane plane(glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, 1.0f));
  const kerf::PlaneRect rect = *plane.boundsInBlock(model.block());
  const glm::vec2 extent = rect.max - rect.min;
  const float pxPerMm = 1024.0f / std::sqrt(extent.x * extent.y);
  kerf::setWorkerThreads(static_cast<int>(state.range(0)));
  // One untimed render: warms up the thread pool and gives the image size and the share inside.
  const kerf::Image first = kerf::renderCut(model, plane, pxPerMm, 1);
  const std::int64_t pixels = static_cast<std::int64_t>(first.width) * first.height;
  std::int64_t inside = 0;
  for (int y = 0; y < first.height; ++y)
    for (int x = 0; x < first.width; ++x) inside += first.pixel(x, y)[3] > 0.0f;
  for (auto _ : state) {
    kerf::Image image = kerf::renderCut(model, plane, pxPerMm, 1);
    benchmark::DoNotOptimize(image.pixels.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * pixels);
  state.counters["inside"] = static_cast<double>(inside) / static_cast<double>(pixels);
  state.SetLabel(std::to_string(first.width) + "x" + std::to_string(first.height) + " px, threads " +
                 std::to_string(kerf::workerThreads()));
  kerf::setWorkerThreads(0);
}
BENCHMARK(BM_RenderCut)->ArgName("threads")->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_RenderCut)
    ->ArgName("threads")
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();

// The six faces of the 40 mm block at 6.4 px/mm (256 x 256 each), samples 1.
void BM_RenderFaces(benchmark::State& state) {
  const kerf::WoodModel& model = demoModel();
  kerf::setWorkerThreads(static_cast<int>(state.range(0)));
  std::int64_t pixels = 0;
  for (auto _ : state) {
    std::array<kerf::Image, 6> faces = kerf::renderFaces(model, 6.4f, 1);
    benchmark::DoNotOptimize(faces[5].pixels.data());
    benchmark::ClobberMemory();
    pixels = 0;
    for (const kerf::Image& face : faces) pixels += static_cast<std::int64_t>(face.width) * face.height;
  }
  state.SetItemsProcessed(state.iterations() * pixels);
  state.SetLabel("threads " + std::to_string(kerf::workerThreads()));
  kerf::setWorkerThreads(0);
}
BENCHMARK(BM_RenderFaces)->ArgName("threads")->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_RenderFaces)
    ->ArgName("threads")
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
