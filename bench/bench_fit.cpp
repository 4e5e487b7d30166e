// Growth-field fitting on the real Mokume sample CN03 (../shared/data/mokume/CN03, the authors' U-Net
// ring-localization images as input): the whole pipeline of `kerf-cli fit` (contours, anatomy prior from
// the photos, pith grid search and refinement, distortions with the grey-map image term, ring
// placement), and step 2 alone. Skipped when ../shared is absent. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "fit/distortion_fit.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/iso_contours.hpp"
#include "io/image.hpp"
#include "util/parallel.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

bool loadCN03(GrowthFieldFitInput& input) {
  const fs::path folder = fs::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
  if (!fs::is_directory(folder)) return false;
  for (FaceId f : kAllFaces) {
    const std::string letter(1, faceLetter(f));
    input.rings[faceIndex(f)] = readRingLocalizationImage(folder / (letter + "_arl-unet.png"));
    input.photos[faceIndex(f)] = readImage(folder / (letter + "_col.png"));
  }
  return true;
}

void BM_FitCN03(benchmark::State& state) {
  GrowthFieldFitInput input;
  if (!loadCN03(input)) {
    state.SkipWithError("../shared/data/mokume/CN03 not found");
    return;
  }
  setWorkerThreads(static_cast<int>(state.range(0)));
  GrowthFieldFitReport report;
  for (auto _ : state) {
    const GrowthFieldFitResult fit = fitGrowthFieldToSample(input, Block{}, WoodParameters{});
    report = fit.report;
    benchmark::DoNotOptimize(fit.rates);
  }
  state.counters["pith_s"] = report.pith.gridSeconds + report.pith.refineSeconds;
  state.counters["distortions_s"] = report.distortionSeconds;
  state.counters["error_rings"] = report.finalLossRings;
  setWorkerThreads(0);
}
BENCHMARK(BM_FitCN03)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
