#pragma once
// Hash-based noise for the procedural model: the C++-style interface to the single-source kernels of
// core/model/kernels/noise.glsl (the shaders compile the same text). Integer hashing (no sin-hash), so
// the same values come out on the CPU and in GLSL >= 3.30.
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/noise_kernels.hpp"

namespace kerf::noise {

// 32-bit integer mixing hash (xorshift-multiply, "lowbias32" constants by C. Wellons).
inline std::uint32_t mix(std::uint32_t x) {
  return glsl::NoiseKernels{}.mixHash(x);
}
inline std::uint32_t hash(std::int32_t a, std::uint32_t seed) {
  return glsl::NoiseKernels{}.hash1(a, seed);
}
inline std::uint32_t hash(std::int32_t a, std::int32_t b, std::uint32_t seed) {
  return glsl::NoiseKernels{}.hash2(a, b, seed);
}
inline std::uint32_t hash(std::int32_t a, std::int32_t b, std::int32_t c, std::uint32_t seed) {
  return glsl::NoiseKernels{}.hash3(a, b, c, seed);
}
// Uniform in [0, 1) from a hash.
inline float unit(std::uint32_t h) {
  return glsl::NoiseKernels{}.unitOf(h);
}
// Uniform in [-1, 1).
inline float signedUnit(std::uint32_t h) {
  return glsl::NoiseKernels{}.signedUnitOf(h);
}
inline float fade(float t) {
  return glsl::NoiseKernels{}.fadeCurve(t);
}
inline float fadeDerivative(float t) {
  return glsl::NoiseKernels{}.fadeDerivative(t);
}
// Smooth 1D value noise in [-1, 1] with lattice spacing 1.
inline float value1(float x, std::uint32_t seed) {
  return glsl::NoiseKernels{}.valueNoise1(x, seed);
}
// Smooth 3D value noise in [-1, 1] and its gradient: (value, d/dx, d/dy, d/dz).
inline glm::vec4 value3(glm::vec3 p, std::uint32_t seed) {
  return glsl::NoiseKernels{}.valueNoise3(p, seed);
}
// Two octaves of value3 (amplitudes 1 and 0.5, roughly in [-1.5, 1.5]) with the gradient.
inline glm::vec4 fractal3(glm::vec3 p, std::uint32_t seed) {
  return glsl::NoiseKernels{}.fractalNoise3(p, seed);
}

}  // namespace kerf::noise
