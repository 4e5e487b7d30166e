#pragma once
// How sure the growth-field fit is, inside the block (issue 18 item 4): the 1-sigma uncertainty of where a
// ring lies, in mm, on a grid of nodes over the block, and the field it belongs to. Estimated by
// fit/ring_uncertainty_fit.hpp; stored in the project (optional key "ring_uncertainty"); drawn over cuts by
// the editor and exported as a volume.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

// The 1-sigma ring-position uncertainty on a regular grid of nodes spanning the block, corner to corner.
struct RingUncertainty {
  glm::ivec3 nodes{0};
  std::vector<float> sigmaMm;  // node (i, j, k) at i + nodes.x * (j + nodes.y * k)
  int replicates = 0;          // the refits it was estimated from
  float calibration = 1;       // the factor applied to their spread
  // The field it belongs to (fieldFingerprint): a refit or an edit of the field makes it stale.
  std::uint64_t field = 0;

  bool empty() const { return sigmaMm.empty(); }
  // Trilinear between the nodes; points outside the block take the nearest boundary's value.
  float at(const Block& block, glm::vec3 pMm) const;
  // Over the nodes, e.g. 0.5: the median.
  float quantile(double q) const;
  // Throws InputError when the node count, the values (finite, >= 0) or the sizes disagree.
  void validate() const;
};

// A fingerprint of what places the rings: the pith, the ring width and phase, the rates and the knots.
std::uint64_t fieldFingerprint(const WoodParameters& params, const GrowthRates& rates,
                               const std::vector<BlockKnot>& knots);

// The uncertainty of a ring position from several fields' years at one point: the RMS of the phase
// differences (year - ring offset) to the reference, each wrapped to [-0.5, 0.5) rings, times the local
// ring spacing (mm).
float ringPositionSigmaMm(float referenceYear, float referenceOffset, const std::vector<float>& years,
                          const std::vector<float>& offsets, float ringSpacingMm);

}  // namespace kerf
