// How well the fit's ring uncertainty (fit/ring_uncertainty_fit.hpp) covers the truth, on synthetic
// blocks whose field is known: each block's faces are rendered by Kerf's model, its rings detected by
// Kerf's detector, the field fitted and refitted on resampled contours, and the fit's error at every node
// compared with the node's raw (uncalibrated) sigma. Prints one row per block; the calibration factor
// that makes the 1-sigma band hold the truth at 68 % of all blocks' nodes (kRingUncertaintyCalibration);
// and, to check it on blocks it was not measured on, each block's coverage with the factor measured on
// the other blocks (leave one block out). Not a test: it takes minutes.
// Usage: kerf_calibrate_ring_uncertainty [replicates]   (docs/fitting.md "How sure the fit is")
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fit/ring_uncertainty_fit.hpp"
#include "synthetic_photo_block.hpp"
#include "util/resource_usage.hpp"

using namespace kerf;

int main(int argc, char** argv) {
  const int replicates = argc > 1 ? std::atoi(argv[1]) : 8;
  const std::vector<testing::SyntheticBlockSpec> blocks = {
      {"kuri", 1, {70, 0, -40}, 4, 30},    {"sugi", 2, {-90, 0, 30}, 2, 200},
      {"nara", 3, {40, 0, 55}, 6, 120},    {"hinoki", 4, {120, 0, 20}, 3, 300},
      {"keyaki", 5, {-60, 0, -60}, 5, 80}, {"beech", 6, {30, 0, -45}, 2, 10},
      {"kuri", 7, {-45, 0, 80}, 7, 250},   {"sugi", 8, {100, 0, 100}, 3, 160},
      {"maple", 9, {-35, 0, -50}, 3, 45},  {"cherry", 10, {150, 0, -60}, 5, 330},
      {"nara", 12, {-80, 0, 40}, 8, 20},   {"hinoki", 13, {50, 0, 38}, 2, 270},
  };
  std::printf("%-8s %4s | %8s %8s %8s %8s\n", "species", "seed", "sigma", "error", "cov@1", "scale68");
  std::vector<RingErrorsAtNodes> results;
  for (const testing::SyntheticBlockSpec& spec : blocks) {
    const Stopwatch clock;
    const testing::SyntheticPhotoBlock b(spec);
    const GrowthFieldFitResult fit = fitGrowthFieldToSample(b.input, b.block, b.fitStart, b.options);
    RingUncertaintyOptions options;
    options.replicates = replicates;
    options.calibration = 1.0f;  // raw bootstrap spread: the factor is what this program measures
    const RingUncertainty u = estimateRingUncertainty(b.input, b.block, fit, b.options, options);
    const WoodModel truth(b.block, b.truth, b.truthRates);
    const WoodModel fitted(b.block, fit.params, *fit.rates, fit.knots);
    results.push_back(ringErrorsAgainstTruth(truth, fitted, u));
    const RingErrorsAtNodes& e = results.back();
    std::vector<float> errors = e.errorMm;
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    std::printf("%-8s %4d | %8.3f %8.3f %8.2f %8.2f   (%.0f s)\n", spec.species.c_str(), spec.seed,
                u.quantile(0.5), errors[errors.size() / 2], e.coverage(1), e.scaleForCoverage(0.68),
                clock.seconds());
    std::fflush(stdout);
  }
  const auto pooled = [&](std::size_t leaveOut) {
    RingErrorsAtNodes all;
    for (std::size_t i = 0; i < results.size(); ++i) {
      if (i == leaveOut) continue;
      all.errorMm.insert(all.errorMm.end(), results[i].errorMm.begin(), results[i].errorMm.end());
      all.sigmaMm.insert(all.sigmaMm.end(), results[i].sigmaMm.begin(), results[i].sigmaMm.end());
    }
    return all;
  };
  std::printf("calibration factor (68 %% of all blocks' nodes): %.3f\n",
              pooled(results.size()).scaleForCoverage(0.68));
  double sum = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const float scale = pooled(i).scaleForCoverage(0.68);
    const double coverage = results[i].coverage(scale);
    sum += coverage;
    std::printf("left out: %-8s %4d  factor of the others %.3f  coverage %.2f\n", blocks[i].species.c_str(),
                blocks[i].seed, scale, coverage);
  }
  std::printf("leave one block out: mean coverage %.2f (target 0.68)\n", sum / double(results.size()));
  return 0;
}
