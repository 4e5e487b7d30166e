#pragma once
// The procedural wood texture: the forward model of Liu et al. 2016 (Sec. 4) as simplified and
// extended by Mokume Sec. 5.3.1 / A.2.3, evaluated on top of the growth field. For a point in the
// block it gives the growth time, the colour and the fibre direction.
//
// Colour follows Beer's law (Liu 4.3): every colour is earlywood * (latewood/earlywood)^t, t being
// the pigment concentration: 0 in earlywood, 1 in latewood, plus 1D ring noise and 3D mottling
// (Liu 4.4), fibre streaks, and pores (Liu 4.6) which raise t. Heartwood and sapwood each have an
// earlywood/latewood pair (Mokume's radial colour maps, A.2.3). Rays (Liu 4.6) blend towards their
// own colour. A per-face tint models differences between photographed faces (Mokume A.2.3).
#include <cstdint>
#include <glm/vec3.hpp>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

struct WoodSample {
  float year = 0;                  // growth field value G (years since the pith) at the distorted point
  float latewood = 0;              // season blend s in [0, 1]: 0 earlywood, 1 latewood
  float pigment = 0;               // Beer's-law concentration t: colour = early * (late / early)^t
  float pore = 0;                  // pore weight in [0, 1] (Wyvill kernel)
  float ray = 0;                   // ray weight in [0, 1]
  glm::vec3 color{0.0f};           // RGB in [0, 1], as stored in 8-bit images (sRGB-encoded)
  glm::vec3 fiberDirection{0.0f};  // unit, block frame (only when asked for)
};

class WoodMaterial {
 public:
  // The field, the parameters and the knots must outlive the material. Knots (Mokume Sec. 5.2.4) are
  // merged into the growth time and darken the wood; nullptr or empty: none.
  WoodMaterial(const WoodParameters& params, const GrowthField& field, const BlockKnots* knots = nullptr);

  // faceIndex 0..5 (A..F) applies that face's tint; -1 (cuts, volumes) applies none.
  WoodSample evaluate(glm::vec3 pMm, int faceIndex = -1, bool withFiberDirection = false) const;
  // Only the growth time at the (distorted) point: WoodSample::year without the texture's cost.
  float year(glm::vec3 pMm) const;

  const GrowthField& field() const { return field_; }
  // The hash seed derived from model.seed (the GLSL port takes it as a uniform).
  std::uint32_t hashSeed() const { return seed_; }
  const WoodParameters& params() const { return params_; }

 private:
  // Liu Eq. 1: the distortion f(p) = p + m_r r + m_theta theta, returning the undistorted point, and
  // (when asked) the distorted fibre direction J^-1 V with J compressed as in Liu Eq. 3.
  glm::vec3 undistort(glm::vec3 p, const Cylindrical& c, glm::vec3* fiberDirection) const;
  float seasonOf(float year) const;
  float poreWeight(const Cylindrical& c, float season) const;
  float rayWeight(const Cylindrical& c) const;

  const WoodParameters& params_;
  const GrowthField& field_;
  const BlockKnots* knots_;
  std::uint32_t seed_;
};

}  // namespace kerf
