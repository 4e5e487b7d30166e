#pragma once
// The procedural wood texture: the forward model of Liu et al. 2016 (Sec. 4) as simplified and
// extended by Mokume Sec. 5.3.1 / A.2.3, evaluated on top of the growth field. For a point in the
// block it gives the growth time, the colour and the fibre direction.
//
// The model itself is written once, in core/model/kernels/wood.glsl, and compiled both here (through
// material/wood_kernels.hpp) and into the shaders of the 3D view (issue 15); see that file for the paper
// sections. This class owns the CPU back-end of it.
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "material/wood_kernels.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

// year, latewood, pigment, pore, ray, color, fiberDirection: see core/model/kernels/wood.glsl.
using WoodSample = glsl::WoodKernels::WoodSample;
// Where a point lies in the tree (growth time, knot, undistorted frame): see kernels/wood.glsl.
using WoodLocation = glsl::WoodKernels::WoodLocation;
// The parts of shade() that groups of texture parameters set on their own: see kernels/wood.glsl.
using WoodLayers = glsl::WoodKernels::WoodLayers;

class WoodMaterial {
 public:
  // The field, the parameters and the knots must outlive the material. Knots (Mokume Sec. 5.2.4) are
  // merged into the growth time and darken the wood; nullptr or empty: none.
  WoodMaterial(const WoodParameters& params, const GrowthField& field, const BlockKnots* knots = nullptr);

  // faceIndex 0..5 (A..F) applies that face's tint; -1 (cuts, volumes) applies none. Without
  // withFiberDirection, WoodSample::fiberDirection is the pith direction.
  WoodSample evaluate(glm::vec3 pMm, int faceIndex = -1, bool withFiberDirection = false) const {
    return kernels_.evaluateWood(pMm, faceIndex, withFiberDirection);
  }
  // evaluate() in two steps: locate() depends on the field and the parameters of its distortion only,
  // so a location may be shaded again under other texture parameters (see kernels/wood.glsl).
  WoodLocation locate(glm::vec3 pMm, bool withFiberDirection = false) const {
    return kernels_.locateWood(pMm, withFiberDirection);
  }
  WoodSample shade(const WoodLocation& location, int faceIndex = -1) const {
    return kernels_.shadeWood(location, faceIndex);
  }
  // shade() in two steps (the texture search reuses a layer across candidates that agree on its
  // parameters): shade(l, f) == compose(l, layers(l), f), bit for bit.
  WoodLayers layers(const WoodLocation& location) const { return kernels_.woodLayers(location); }
  WoodSample compose(const WoodLocation& location, const WoodLayers& layers, int faceIndex = -1) const {
    return kernels_.composeWood(location, layers, faceIndex);
  }
  // The layers one at a time (what layers() puts in each member).
  float latewoodLayer(const WoodLocation& w) const { return kernels_.seasonOf(w.year); }
  float poreLayer(const WoodLocation& w) const { return kernels_.poreWeight(w.c, w.year); }
  float rayLayer(const WoodLocation& w) const { return kernels_.rayWeight(w.c); }
  float fiberLayer(const WoodLocation& w) const { return kernels_.fiberLayer(w.c); }
  void ringLayers(const WoodLocation& w, WoodLayers& l) const {
    l.ringProfile = kernels_.ringProfileAt(w.year);
    l.ringNoise = kernels_.ringNoiseAt(w.year);
    l.mottle = kernels_.mottleAt(w.c);
  }
  // Only the growth time at the (distorted) point: WoodSample::year without the texture's cost.
  float year(glm::vec3 pMm) const { return kernels_.woodYear(pMm); }
  // The fitted ring profile (rings.profile_*) at a growth time: the pigment it adds, and which of its
  // eight knots (k-1 .. k+2, modulo 8) weigh how much there.
  float yearPhase(float year) const { return kernels_.yearPhase(year); }  // 0 at a ring boundary .. 1
  float ringProfile(float year) const { return kernels_.ringProfileAt(year); }
  int ringProfileCell(float year, glm::vec4& weights) const {
    return kernels_.ringProfileCell(year, weights);
  }

  const GrowthField& field() const { return field_; }
  // The hash seed derived from model.seed (the shaders take it as the uniform u_hashSeed).
  std::uint32_t hashSeed() const { return kernels_.u_hashSeed; }
  const WoodParameters& params() const { return kernels_.P; }

 private:
  const GrowthField& field_;
  // The kernels only read their members; GLSL functions cannot be declared const.
  mutable glsl::WoodKernels kernels_;
};

}  // namespace kerf
