#pragma once
// The model's hash and value noise (kernels/noise.glsl) compiled for the CPU: the same source as the
// shaders' (issue 15). Stateless; kerf::noise (model/noise.hpp) is the C++-style interface to it.
#include "model/glsl_compat.hpp"

namespace kerf::glsl {

struct NoiseKernels {
#include "model/kernels/noise.glsl"
};

}  // namespace kerf::glsl
