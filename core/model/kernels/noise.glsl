// Hash-based noise of the procedural model, single source for the core and the shaders (issue 15;
// core/model/glsl_compat.hpp has the rules). Integer hashing, not sin-hashing, so the same values come
// out on the CPU and in GLSL >= 3.30, whatever the GPU's sin precision.

KERF_CONST float kPi = 3.14159265358979f;

// 32-bit integer mixing hash (xorshift-multiply, "lowbias32" constants by C. Wellons).
uint mixHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}
uint hash1(int a, uint seed) { return mixHash(uint(a) ^ mixHash(seed)); }
uint hash2(int a, int b, uint seed) { return mixHash(uint(b) ^ hash1(a, seed)); }
uint hash3(int a, int b, int c, uint seed) { return mixHash(uint(c) ^ hash2(a, b, seed)); }
// Uniform in [0, 1) and in [-1, 1) from a hash.
float unitOf(uint h) { return float(h >> 8u) * (1.0f / 16777216.0f); }
float signedUnitOf(uint h) { return unitOf(h) * 2.0f - 1.0f; }

float fadeCurve(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
float fadeDerivative(float t) { return 30.0f * t * t * (t * (t - 2.0f) + 1.0f); }

// Smooth 1D value noise in [-1, 1] with lattice spacing 1.
float valueNoise1(float x, uint seed) {
  float fl = floor(x);
  int i = int(fl);
  float t = fadeCurve(x - fl);
  float a = signedUnitOf(hash1(i, seed));
  float b = signedUnitOf(hash1(i + 1, seed));
  return a + t * (b - a);
}

// Smooth 3D value noise in [-1, 1] and its gradient: (value, d/dx, d/dy, d/dz).
vec4 valueNoise3(vec3 p, uint seed) {
  vec3 fl = floor(p);
  int ix = int(fl.x);
  int iy = int(fl.y);
  int iz = int(fl.z);
  vec3 f = p - fl;
  vec3 u = vec3(fadeCurve(f.x), fadeCurve(f.y), fadeCurve(f.z));
  vec3 du = vec3(fadeDerivative(f.x), fadeDerivative(f.y), fadeDerivative(f.z));
  float a = signedUnitOf(hash3(ix, iy, iz, seed));
  float b = signedUnitOf(hash3(ix + 1, iy, iz, seed));
  float c = signedUnitOf(hash3(ix, iy + 1, iz, seed));
  float d = signedUnitOf(hash3(ix + 1, iy + 1, iz, seed));
  float e = signedUnitOf(hash3(ix, iy, iz + 1, seed));
  float g = signedUnitOf(hash3(ix + 1, iy, iz + 1, seed));
  float h = signedUnitOf(hash3(ix, iy + 1, iz + 1, seed));
  float k = signedUnitOf(hash3(ix + 1, iy + 1, iz + 1, seed));
  // Trilinear blend written as a polynomial in u so the derivative follows directly.
  float k1 = b - a;
  float k2 = c - a;
  float k3 = e - a;
  float k4 = a - b - c + d;
  float k5 = a - c - e + h;
  float k6 = a - b - e + g;
  float k7 = -a + b + c - d + e - g - h + k;
  float v = a + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z + k6 * u.z * u.x +
            k7 * u.x * u.y * u.z;
  vec3 grad = vec3(du.x * (k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z),
                   du.y * (k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x),
                   du.z * (k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y));
  return vec4(v, grad);
}

// Two octaves of valueNoise3 (amplitudes 1 and 0.5, roughly in [-1.5, 1.5]) with the gradient.
vec4 fractalNoise3(vec3 p, uint seed) {
  vec4 a = valueNoise3(p, seed);
  vec4 b = valueNoise3(p * 2.03f + vec3(17.1f, 3.7f, 9.3f), seed + 101u);
  return a + vec4(0.5f * b.x, 1.015f * b.y, 1.015f * b.z, 1.015f * b.w);  // d/dp 0.5 n(2.03 p)
}
