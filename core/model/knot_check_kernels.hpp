#pragma once
// The knot checks (kernels/knot_checks.glsl) compiled for the CPU: the same source as the shaders'
// (issue 15's single-source kernels). Stateless; knotCheckShade is the C++-style interface to it, called by
// the log's knots (field/knot_field.cpp) and the block's (field/block_knots.cpp).
#include "model/noise_kernels.hpp"

namespace kerf::glsl {

struct KnotCheckKernels : NoiseKernels {
#include "model/kernels/knot_checks.glsl"
};

}  // namespace kerf::glsl

namespace kerf {

// The colour factor of a knot's checks at a point (1 = no crack); the arguments are the kernel's.
inline float knotCheckShade(int knot, float distance, float radius, float beta, float along, float stemTime,
                            float deathTime, float strength) {
  return glsl::KnotCheckKernels{}.knotCheckShade(knot, distance, radius, beta, along, stemTime, deathTime,
                                                 strength);
}

}  // namespace kerf
