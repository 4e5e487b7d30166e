#include "fit/ring_uncertainty_fit.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>

#include "field/pith_axis.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

namespace {

glm::vec3 nodePosition(const Block& block, glm::ivec3 nodes, int i, int j, int k) {
  const glm::vec3 t(nodes.x > 1 ? float(i) / float(nodes.x - 1) : 0.5f,
                    nodes.y > 1 ? float(j) / float(nodes.y - 1) : 0.5f,
                    nodes.z > 1 ? float(k) / float(nodes.z - 1) : 0.5f);
  return -block.halfSize() + t * block.size();
}

// Ring phase (0 at every ring) of a model at p.
float phaseAt(const WoodModel& model, glm::vec3 p) {
  return model.material().year(p) - model.params().ringOffset;
}

// Local ring spacing in mm: 1 / |grad phase|, by central differences.
float ringSpacingMm(const WoodModel& model, glm::vec3 p) {
  constexpr float h = 0.25f;
  glm::vec3 g;
  for (int a = 0; a < 3; ++a) {
    glm::vec3 d(0.0f);
    d[a] = h;
    g[a] = (phaseAt(model, p + d) - phaseAt(model, p - d)) / (2 * h);
  }
  const float length = glm::length(g);
  return length > 1e-6f ? 1.0f / length : 0.0f;
}

}  // namespace

RingUncertainty estimateRingUncertainty(const GrowthFieldFitInput& input, const Block& block,
                                        const GrowthFieldFitResult& fitted,
                                        const GrowthFieldFitOptions& fitOptions,
                                        const RingUncertaintyOptions& options, const Progress& progress) {
  if (!fitted.rates) throw InputError("the fit has no growth rates: its uncertainty needs a full fit");
  if (options.replicates < 2) throw InputError("the uncertainty needs at least 2 refits");
  const WoodParameters& params = fitted.params;
  const WoodModel reference(block, params, *fitted.rates, fitted.knots);

  GrowthFieldFitOptions replicate = fitOptions;
  replicate.fitAlternative = false;
  replicate.pithSideByPores = false;
  replicate.earlywoodByPores = false;  // the reference's phase goes to every refit below
  replicate.fitColours = false;
  replicate.fitKnots = false;  // the fitted knots are merged into every replicate below
  replicate.preview = nullptr;
  replicate.minContours = 0;
  replicate.minFaces = 0;
  replicate.pithStart = PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth);
  GrowthFieldFitInput replicateInput = input;
  replicateInput.knotMarks.clear();

  std::vector<std::unique_ptr<const WoodModel>> models;
  for (int r = 0; r < options.replicates; ++r) {
    progress.throwIfCancelled();
    replicate.resampleContoursSeed = options.seed * 1000003ull + static_cast<std::uint64_t>(r);
    const double from = double(r) / options.replicates, to = double(r + 1) / options.replicates;
    const GrowthFieldFitResult refit =
        fitGrowthFieldToSample(replicateInput, block, params, replicate, progress.part(from, 0.97 * to));
    if (!refit.rates) continue;
    // One phase for all: without numbered traces a refit puts its rings at whole years, and where the
    // earlywood starts against them (the fit's shift by the pores, or the user's own ring_offset) is the
    // reference's. The refits differ in their rings, not in that.
    WoodParameters refitParams = refit.params;
    if (refit.report.numberedTraces == 0) refitParams.ringOffset = params.ringOffset;
    models.push_back(std::make_unique<const WoodModel>(block, refitParams, *refit.rates, fitted.knots));
  }
  if (models.size() < 2) throw InputError("too few refits succeeded to say how sure the fit is");

  RingUncertainty out;
  const float step = std::max({block.size().x, block.size().y, block.size().z}) /
                     float(std::max(2, options.nodesAlongLongestSide) - 1);
  out.nodes = glm::max(glm::ivec3(glm::round(block.size() / step)) + 1, 2);
  out.sigmaMm.resize(static_cast<std::size_t>(out.nodes.x) * out.nodes.y * out.nodes.z);
  out.replicates = static_cast<int>(models.size());
  out.calibration = options.calibration;
  out.field = fieldFingerprint(params, *fitted.rates, fitted.knots);
  parallelRows(out.nodes.z, [&](int k) {
    std::vector<float> years(models.size()), offsets(models.size());
    for (int j = 0; j < out.nodes.y; ++j)
      for (int i = 0; i < out.nodes.x; ++i) {
        const glm::vec3 p = nodePosition(block, out.nodes, i, j, k);
        for (std::size_t r = 0; r < models.size(); ++r) {
          years[r] = models[r]->material().year(p);
          offsets[r] = models[r]->params().ringOffset;
        }
        out.sigmaMm[static_cast<std::size_t>(i + out.nodes.x * (j + out.nodes.y * k))] =
            options.calibration * ringPositionSigmaMm(reference.material().year(p), params.ringOffset, years,
                                                      offsets, ringSpacingMm(reference, p));
      }
  });
  progress.set(1.0);
  return out;
}

double RingErrorsAtNodes::coverage(float scale) const {
  if (errorMm.empty()) return 0.0;
  std::size_t inside = 0;
  for (std::size_t i = 0; i < errorMm.size(); ++i) inside += errorMm[i] <= scale * sigmaMm[i] ? 1 : 0;
  return double(inside) / double(errorMm.size());
}

float RingErrorsAtNodes::scaleForCoverage(double share) const {
  std::vector<float> ratios;
  for (std::size_t i = 0; i < errorMm.size(); ++i)
    ratios.push_back(sigmaMm[i] > 0 ? errorMm[i] / sigmaMm[i] : (errorMm[i] > 0 ? 1e9f : 0.0f));
  if (ratios.empty()) return 1.0f;
  const auto k = static_cast<std::ptrdiff_t>(std::clamp(share, 0.0, 1.0) * double(ratios.size() - 1));
  std::nth_element(ratios.begin(), ratios.begin() + k, ratios.end());
  return ratios[static_cast<std::size_t>(k)];
}

RingErrorsAtNodes ringErrorsAgainstTruth(const WoodModel& truth, const WoodModel& fitted,
                                         const RingUncertainty& uncertainty) {
  RingErrorsAtNodes out;
  const Block& block = truth.block();
  for (int k = 0; k < uncertainty.nodes.z; ++k)
    for (int j = 0; j < uncertainty.nodes.y; ++j)
      for (int i = 0; i < uncertainty.nodes.x; ++i) {
        const glm::vec3 p = nodePosition(block, uncertainty.nodes, i, j, k);
        float d = phaseAt(fitted, p) - phaseAt(truth, p);
        d -= std::floor(d + 0.5f);
        out.errorMm.push_back(std::abs(d) * ringSpacingMm(truth, p));
        out.sigmaMm.push_back(
            uncertainty
                .sigmaMm[static_cast<std::size_t>(i + uncertainty.nodes.x * (j + uncertainty.nodes.y * k))]);
      }
  return out;
}

}  // namespace kerf
