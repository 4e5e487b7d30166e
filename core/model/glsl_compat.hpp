#pragma once
// The C++ side of the model's single-source kernels (core/model/kernels/*.glsl, issue 15).
//
// The kernels are written once in the subset of GLSL 3.30 that is also C++20 with GLM (GLM mirrors
// GLSL's types and built-ins; Blender's GPU_shader_shared_utils.h is the precedent). The shaders
// include them as text (gpu/wood_program.cpp); the core includes them inside a struct
// (model/noise_kernels.hpp, material/wood_kernels.hpp), so their functions become inline member
// functions that see the struct's members as the shaders see uniforms.
//
// Rules of the subset, checked by both compilers (tests/core/test_kernel_sources.cpp checks the rest):
// - float literals carry an `f` (1.0f): GLSL 3.30 accepts it, and C++ would otherwise compute in double;
// - no overloads (GLSL allows them, but a C++ float/int overload can silently pick another function);
// - `KERF_OUT(T) x` for out parameters, `KERF_CONST` for constants, `KERF_BOOL_ARG` not needed: plain bool;
// - no preprocessor lines in the kernel files (they are included into a struct body in C++).
#include <cstdint>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#define KERF_OUT(T) T&
#define KERF_CONST static constexpr

namespace kerf::glsl {

using namespace glm;  // vec3, floor, clamp, mix, pow, dot, ... as in GLSL
using uint = std::uint32_t;

}  // namespace kerf::glsl
