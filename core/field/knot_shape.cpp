#include "field/knot_shape.hpp"

#include <algorithm>
#include <cmath>

namespace kerf {

KnotShape describeKnot(const Knot& knot) {
  KnotShape shape;
  shape.heightMm = knot.heights.front();
  shape.azimuthRad = knot.azimuths.front();
  shape.lengthMm = knot.maxDistance();
  shape.twistRad = knot.azimuths.back() - knot.azimuths.front();
  shape.deathDistanceMm = knot.deathDistance;
  // Least squares of z - z0 = bend sqrt(d) + rise d (2 x 2 normal equations).
  double ss = 0, sl = 0, ll = 0, sz = 0, lz = 0;
  for (int j = 1; j < knot.samples(); ++j) {
    const double d = knot.distanceStep * j, s = std::sqrt(d), z = knot.heights[j] - knot.heights[0];
    ss += s * s;
    sl += s * d;
    ll += d * d;
    sz += s * z;
    lz += d * z;
  }
  const double det = ss * ll - sl * sl;
  if (std::abs(det) > 1e-9 * ss * ll) {
    shape.bend = static_cast<float>((sz * ll - lz * sl) / det);
    shape.rise = static_cast<float>((ss * lz - sl * sz) / det);
  } else {
    shape.bend = 0.0f;
    shape.rise = ll > 0 ? static_cast<float>(lz / ll) : 0.0f;
  }
  return shape;
}

Knot makeKnot(const KnotShape& shape, float distanceStep, float endDistance) {
  Knot knot;
  knot.distanceStep = distanceStep;
  const int samples = std::max(2, static_cast<int>(std::ceil(shape.lengthMm / distanceStep - 1e-4f)) + 1);
  const float twistScale = 1.0f / std::log1p(std::max(shape.lengthMm, 1e-3f));
  knot.heights.resize(samples);
  knot.azimuths.resize(samples);
  for (int j = 0; j < samples; ++j) {
    const float d = distanceStep * static_cast<float>(j);
    knot.heights[j] = shape.heightMm + shape.bend * std::sqrt(d) + shape.rise * d;
    knot.azimuths[j] = shape.azimuthRad + shape.twistRad * std::log1p(d) * twistScale;
  }
  knot.deathDistance = shape.deathDistanceMm;
  knot.endDistance = endDistance;
  return knot;
}

}  // namespace kerf
