#pragma once
// The procedural wood texture (model/kernels/wood.glsl) compiled for the CPU: the same source as the
// shaders' (issue 15). This struct is the CPU back-end of that source: its members are what the
// shaders get as uniforms, and it defines the three functions the source expects of a back-end (the
// pith frame, the growth field and the knots, which the GPU reads from textures and uniform arrays).
#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "model/noise_kernels.hpp"
#include "params/parameter_schema.hpp"

namespace kerf::glsl {

struct WoodKernels : NoiseKernels {
  // The field, the parameters and the knots must outlive the kernels; knots may be nullptr.
  WoodKernels(const WoodParameters& params, const GrowthField& field, const BlockKnots* knots, uint seed)
      : P(params),
        u_hashSeed(seed),
        u_axisDirection(field.axis().direction),
        u_axisReference(field.axis().reference),
        u_axisBinormal(field.axis().binormal),
        field_(field),
        knots_(knots) {}

  const WoodParameters& P;
  uint u_hashSeed;
  vec3 u_axisDirection, u_axisReference, u_axisBinormal;

  Cylindrical cylindricalOf(vec3 p, bool withAzimuth) const {
    return field_.axis().toCylindrical(p, withAzimuth);
  }
  float growthAt(const Cylindrical& c) const { return field_.evaluate(c); }
  float mergeKnots(vec3 p, float stemTime, float stemRadius, float& darkness, float& shade) const {
    darkness = 0.0f;
    shade = 1.0f;
    if (!knots_) return stemTime;
    const BlockKnotSample k = knots_->merge(p, stemTime, stemRadius);
    darkness = k.darkness;
    shade = k.shade;
    return k.time;
  }

// The kernels' functions are member functions here; they only read the members above (GLSL has no
// const member functions, so the owner keeps this struct `mutable`).
#include "model/kernels/wood.glsl"

 private:
  const GrowthField& field_;
  const BlockKnots* knots_;
};

}  // namespace kerf::glsl
