#include "render/wood_model.hpp"

#include "io/project.hpp"

namespace kerf {

WoodModel::WoodModel(const Block& block, const WoodParameters& params, const GrowthRates& rates)
    : block_(block) {
  validate(params);
  params_ = std::make_unique<const WoodParameters>(params);
  field_ = std::make_unique<const GrowthField>(*params_, rates);
  material_ = std::make_unique<const WoodMaterial>(*params_, *field_);
}

WoodModel::WoodModel(const Project& project)
    : WoodModel(project.block, project.params, project.effectiveRates()) {}

}  // namespace kerf
