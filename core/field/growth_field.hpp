#pragma once
// The procedural growth field G(omega, p) of Mokume Sec. 5.2.1: omega = [O, V, R]. G is the time, in
// years since the pith, at which the tree laid down the wood at p. Annual rings are its iso-surfaces
// at the ring levels A (here growth.ring_offset + k for whole k).
//
// Construction: the rates R (clamped at 0) are integrated along the radius from the pith into a
// table C of n_h x n_a x (n_r + 1) values (G at every radial node). Along the radius G is linear
// between nodes, as in the paper. Across heights and spokes Kerf blends the columns with uniform
// cubic B-spline weights instead of the paper's (bi)linear ones: the weights are non-negative and sum
// to one, so G is still continuous and monotone along every radius, but rings no longer show a corner
// at every spoke on faces nearly tangent to them. Inside the first node (r < radiusMin) G falls
// linearly to 0 at the pith; beyond the last it continues with the last rate; above/below the height
// range it is constant along the axis; the azimuth is periodic.
#include <vector>

#include "field/growth_rates.hpp"
#include "field/pith_axis.hpp"

namespace kerf {

struct WoodParameters;

class GrowthField {
 public:
  GrowthField(const PithAxis& axis, float ringWidthMm, const GrowthRates& rates);
  // Pith axis and ring width from the parameters (growth.*).
  GrowthField(const WoodParameters& params, const GrowthRates& rates);

  const PithAxis& axis() const { return axis_; }
  float ringWidth() const { return ringWidth_; }
  const GrowthRates& rates() const { return rates_; }

  // G at a point given in cylindrical coordinates of axis().
  float evaluate(const Cylindrical& c) const;
  float evaluate(glm::vec3 pMm) const { return evaluate(axis_.toCylindrical(pMm)); }

  // The integrated table C (years at every radial node), n_h x n_a x (n_r + 1); what the GPU samples.
  const std::vector<float>& cumulative() const { return cumulative_; }

 private:
  float node(int ih, int ia, int ir) const {
    return cumulative_[(static_cast<std::size_t>(ih) * rates_.azimuths + ia) * (rates_.radii + 1) + ir];
  }
  // Where a radius falls on the radial nodes: worked out once per point, used for 16 columns.
  struct RadialPosition {
    enum Region { InsideFirstNode, BetweenNodes, BeyondLastNode } region = BetweenNodes;
    int cell = 0;
    float t = 0.0f;
    float radius = 0.0f;
  };
  RadialPosition radialPosition(float radius) const;
  float radialValue(int ih, int ia, const RadialPosition& position) const;

  PithAxis axis_;
  float ringWidth_;
  GrowthRates rates_;
  std::vector<float> cumulative_;
  float radialStep_;
};

// Ring iso-values A of the field that fall within [gMin, gMax]: offset + k for whole k.
std::vector<float> ringLevels(float ringOffset, float gMin, float gMax);

}  // namespace kerf
