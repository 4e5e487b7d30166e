#pragma once
// Hash-based noise for the procedural model. Integer hashing (no sin-hash), so the same values come out
// on the CPU and in GLSL >= 3.30 (uint arithmetic), independent of the GPU's sin precision.
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace kerf::noise {

// 32-bit integer mixing hash (xorshift-multiply, "lowbias32" constants by C. Wellons).
inline std::uint32_t mix(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
inline std::uint32_t hash(std::int32_t a, std::uint32_t seed) {
  return mix(static_cast<std::uint32_t>(a) ^ mix(seed));
}
inline std::uint32_t hash(std::int32_t a, std::int32_t b, std::uint32_t seed) {
  return mix(static_cast<std::uint32_t>(b) ^ hash(a, seed));
}
inline std::uint32_t hash(std::int32_t a, std::int32_t b, std::int32_t c, std::uint32_t seed) {
  return mix(static_cast<std::uint32_t>(c) ^ hash(a, b, seed));
}
// Uniform in [0, 1) from a hash.
inline float unit(std::uint32_t h) {
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}
// Uniform in [-1, 1).
inline float signedUnit(std::uint32_t h) {
  return unit(h) * 2.0f - 1.0f;
}

inline float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
inline float fadeDerivative(float t) {
  return 30.0f * t * t * (t * (t - 2.0f) + 1.0f);
}

// Smooth 1D value noise in [-1, 1] with lattice spacing 1.
inline float value1(float x, std::uint32_t seed) {
  const float fl = std::floor(x);
  const auto i = static_cast<std::int32_t>(fl);
  const float t = fade(x - fl);
  const float a = signedUnit(hash(i, seed)), b = signedUnit(hash(i + 1, seed));
  return a + t * (b - a);
}

// Smooth 3D value noise in [-1, 1] and its gradient: (value, d/dx, d/dy, d/dz).
inline glm::vec4 value3(glm::vec3 p, std::uint32_t seed) {
  const glm::vec3 fl(std::floor(p.x), std::floor(p.y), std::floor(p.z));
  const auto ix = static_cast<std::int32_t>(fl.x), iy = static_cast<std::int32_t>(fl.y),
             iz = static_cast<std::int32_t>(fl.z);
  const glm::vec3 f = p - fl;
  const glm::vec3 u(fade(f.x), fade(f.y), fade(f.z));
  const glm::vec3 du(fadeDerivative(f.x), fadeDerivative(f.y), fadeDerivative(f.z));
  const float a = signedUnit(hash(ix, iy, iz, seed)), b = signedUnit(hash(ix + 1, iy, iz, seed));
  const float c = signedUnit(hash(ix, iy + 1, iz, seed)), d = signedUnit(hash(ix + 1, iy + 1, iz, seed));
  const float e = signedUnit(hash(ix, iy, iz + 1, seed)), g = signedUnit(hash(ix + 1, iy, iz + 1, seed));
  const float h = signedUnit(hash(ix, iy + 1, iz + 1, seed)),
              k = signedUnit(hash(ix + 1, iy + 1, iz + 1, seed));
  // Trilinear blend written as a polynomial in u so the derivative follows directly.
  const float k1 = b - a, k2 = c - a, k3 = e - a, k4 = a - b - c + d, k5 = a - c - e + h, k6 = a - b - e + g,
              k7 = -a + b + c - d + e - g - h + k;
  const float v = a + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z + k6 * u.z * u.x +
                  k7 * u.x * u.y * u.z;
  const glm::vec3 grad(du.x * (k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z),
                       du.y * (k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x),
                       du.z * (k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y));
  return {v, grad};
}

// Two octaves of value3 (amplitudes 1 and 0.5, roughly in [-1.5, 1.5]) with the gradient.
inline glm::vec4 fractal3(glm::vec3 p, std::uint32_t seed) {
  const glm::vec4 a = value3(p, seed);
  const glm::vec4 b = value3(p * 2.03f + glm::vec3(17.1f, 3.7f, 9.3f), seed + 101u);
  return a + glm::vec4(0.5f * b.x, 1.015f * b.y, 1.015f * b.z, 1.015f * b.w);  // d/dp 0.5 n(2.03 p)
}

}  // namespace kerf::noise
