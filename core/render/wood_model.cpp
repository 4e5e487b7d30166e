#include "render/wood_model.hpp"

namespace kerf {

WoodModel::WoodModel(const Block& block, const WoodParameters& params, const GrowthRates& rates,
                     const std::vector<BlockKnot>& knots)
    : block_(block) {
  validate(params);
  params_ = std::make_unique<const WoodParameters>(params);
  field_ = std::make_unique<const GrowthField>(*params_, rates);
  knots_ = std::make_unique<const BlockKnots>(knots, KnotSettings::fromParameters(*params_),
                                              params_->ringWidth, field_->axis().direction);
  material_ = std::make_unique<const WoodMaterial>(*params_, *field_, knots_.get());
}

}  // namespace kerf
