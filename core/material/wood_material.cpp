#include "material/wood_material.hpp"

#include "model/noise.hpp"

namespace kerf {

WoodMaterial::WoodMaterial(const WoodParameters& params, const GrowthField& field, const BlockKnots* knots)
    : field_(field),
      kernels_(params, field, knots && !knots->empty() ? knots : nullptr,
               noise::mix(static_cast<std::uint32_t>(params.seed) * 7919u + 13u)) {}

}  // namespace kerf
