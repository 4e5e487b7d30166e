// Finished wood in the 3D view. Appended to wood_model.glsl (evaluateWood) by kerf::WoodProgram.
//
// Passes (u_pass): 0 = the block's faces (the part behind the cut, or all of it), 1 = the cut surface,
// 2 = the ghost of the part in front of the cut (flat and translucent, so the cut surface stays
// readable through it), 3 = a placed part (issue 7): the wood without a face tint or edge lines.
//
// Shading, in linear light (the model's colours are sRGB-encoded, like photographs):
// - diffuse: a key light above-left of the viewer, a fill light and a little ambient, balanced so a
//   face seen square-on shows about its own colour;
// - clear coat: a soft Blinn-Phong highlight with Schlick's Fresnel term, weaker on pores and
//   earlywood (Liu et al. 2016 Sec. 4.6: recessed areas hold less finish);
// - fibre highlight: the subsurface fibre reflection of Marschner et al. 2005 as used by Liu et al. 2016
//   (Sec. 2, 4.3, 4.5): light and view are refracted into the finish, the fibres (WoodSample.
//   fiberDirection, from the distortion's Jacobian) reflect light into a cone, a Gaussian of width
//   u_sheenWidth in the half angle psi_h = psi_i + psi_r; its colour is the diffuse colour raised to a
//   power below 1 (Liu 4.3).
in vec3 v_position;
in vec3 v_normal;
in vec2 v_photoUv;

uniform int u_pass;
uniform int u_faceIndex;  // 0..5 = A..F (that face's tint), -1 = the cut surface
uniform vec3 u_blockHalfSize;
uniform bool u_cutEnabled;
uniform vec3 u_cutNormal;
uniform float u_cutOffset;  // the plane is dot(p, u_cutNormal) = u_cutOffset
uniform vec3 u_eye;
uniform vec3 u_keyLight;   // unit, towards the light
uniform vec3 u_fillLight;  // unit, towards the light
uniform bool u_showPhoto;
uniform sampler2D u_photo;
uniform float u_sheenStrength;  // strength of the fibre highlight (0 = off)
uniform float u_sheenWidth;      // Gaussian width (radians)

out vec4 fragColor;

const float kKey = 0.7, kFill = 0.3, kAmbient = 0.25;
const float kEta = 1.5;  // refractive index of the finish
const vec3 kEdgeDark = vec3(0.05, 0.035, 0.02);
const vec3 kCutLine = vec3(1.0, 0.62, 0.18);  // the cut's outline (linear)
const vec3 kGhost = vec3(0.80, 0.82, 0.86);

vec3 toLinear(vec3 c) { return pow(max(c, vec3(0.0)), vec3(2.2)); }
vec3 toDisplay(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

// A direction outside the surface (unit, pointing away) bent into the finish, mirrored back out: the
// outward direction of the refracted ray.
vec3 refractOut(vec3 w, vec3 n) {
  float c = dot(w, n);
  vec3 t = (w - c * n) / kEta;
  return normalize(t + sqrt(max(1.0 - dot(t, t), 0.0)) * n);
}

float fiberLobe(vec3 fiber, vec3 n, vec3 l, vec3 v) {
  vec3 li = refractOut(l, n), vr = refractOut(v, n);
  float psiI = asin(clamp(dot(fiber, li), -1.0, 1.0));
  float psiR = asin(clamp(dot(fiber, vr), -1.0, 1.0));
  float psiH = psiI + psiR, psiD = 0.5 * (psiR - psiI);
  float g = exp(-0.5 * psiH * psiH / (u_sheenWidth * u_sheenWidth)) / (2.5066283 * u_sheenWidth);
  float cd = cos(psiD);
  return g / max(cd * cd, 0.1);
}

vec3 shade(vec3 albedo, vec3 n, vec3 p, vec3 fiber, float gloss, bool withFiber) {
  vec3 a = toLinear(albedo);
  vec3 v = normalize(u_eye - p);
  float nl = max(dot(n, u_keyLight), 0.0);
  float nf = max(dot(n, u_fillLight), 0.0);
  vec3 color = a * (kAmbient + kKey * nl + kFill * nf);
  // Clear coat.
  vec3 h = normalize(u_keyLight + v);
  float nv = max(dot(n, v), 0.0);
  float fresnel = 0.04 + 0.96 * pow(1.0 - nv, 5.0);
  const float shininess = 60.0;
  float coat = fresnel * pow(max(dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.13;
  color += vec3(kKey * nl * coat * gloss);
  // Fibre highlight, seen through the finish, from both lights (the fill comes from below, where the
  // cone reflection of fibres lying along the surface reaches a viewer looking from above).
  if (withFiber && u_sheenStrength > 0.0) {
    vec3 fiberColor = pow(a, vec3(0.5));
    float lobe = kKey * nl * fiberLobe(fiber, n, u_keyLight, v) + kFill * nf * fiberLobe(fiber, n, u_fillLight, v);
    color += u_sheenStrength * (1.0 - fresnel) * gloss * lobe * fiberColor;
  }
  return color;
}

void main() {
  vec3 p = v_position;
  vec3 n = normalize(v_normal);
  if (u_pass == 3 && dot(n, u_eye - p) < 0.0) n = -n;  // a file whose triangles face inwards
  vec3 pixel = fwidth(p);  // block mm per screen pixel along each axis (before any discard)
  float side = dot(p, u_cutNormal) - u_cutOffset;
  float sidePixel = fwidth(side);
  if (u_cutEnabled) {
    if (u_pass == 0 && side > 0.0) discard;
    if (u_pass == 2 && side <= 0.0) discard;
  }

  // Distance in pixels to the block's edges (not along the axis the surface is flat in).
  float edge = 1e6;
  for (int i = 0; i < 3; ++i)
    if (abs(n[i]) < 0.999 && pixel[i] > 1e-7) edge = min(edge, (u_blockHalfSize[i] - abs(p[i])) / pixel[i]);
  float edgeLine = 1.0 - smoothstep(0.3, 1.3, edge);
  float cutLine = u_cutEnabled && u_pass == 0 && sidePixel > 1e-7 ? 1.0 - smoothstep(0.6, 1.8, -side / sidePixel) : 0.0;

  if (u_pass == 2) {  // ghost
    float facing = max(dot(n, normalize(u_eye - p)), 0.0);
    vec3 color = kGhost * (0.55 + 0.45 * facing);
    float alpha = mix(0.09, 0.7, edgeLine);
    fragColor = vec4(toDisplay(color), alpha);
    return;
  }

  vec3 albedo, fiber;
  float gloss = 1.0;
  bool withFiber = true;
  if (u_showPhoto && u_pass <= 1) {  // a photo, or the face's or cut's own appearance (issue 17)
    albedo = texture(u_photo, v_photoUv).rgb;
    fiber = u_axisDirection;
    withFiber = false;
  } else {
#ifdef KERF_BOARD_WOOD
    WoodSample s = boardWood(p);  // a board cut from a log (board_wood.glsl)
#else
    WoodSample s = evaluateWood(p, u_pass == 1 || u_pass == 3 ? -1 : u_faceIndex, true);  // the sheen needs the fibres
#endif
    albedo = s.color;
    fiber = s.fiberDirection;
    gloss = (1.0 - 0.6 * s.pore) * mix(0.7, 1.0, s.latewood);
  }
  vec3 color = shade(albedo, n, p, fiber, gloss, withFiber);
  if (u_pass == 1) {
    color = mix(color, kCutLine, 0.9 * (1.0 - smoothstep(0.8, 2.0, edge)));
  } else if (u_pass == 0) {
    color = mix(color, color * 0.45 + kEdgeDark, 0.8 * edgeLine);
    color = mix(color, kCutLine, 0.9 * cutLine);
  }
  fragColor = vec4(toDisplay(color), 1.0);
}
