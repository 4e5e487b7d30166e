#pragma once
// Uniform cubic B-spline weights of the growth field's blending across heights and spokes: non-negative
// and summing to 1, so G stays monotone along the radius, and C2 across spokes and height levels
// (trilinear weights leave a visible corner in the rings on faces nearly tangent to them, at every
// spoke). Shared by GrowthField (float) and the distortion fit's coefficients (double), so both use the
// same interpolation; shaders/wood_model.glsl has the GLSL twin.
namespace kerf {

template <class T>
void bsplineWeights(T t, T w[4]) {
  const T s = T(1) - t, t2 = t * t, t3 = t2 * t;
  w[0] = s * s * s / T(6);
  w[1] = (T(3) * t3 - T(6) * t2 + T(4)) / T(6);
  w[2] = (T(-3) * t3 + T(3) * t2 + T(3) * t + T(1)) / T(6);
  w[3] = t3 / T(6);
}

}  // namespace kerf
