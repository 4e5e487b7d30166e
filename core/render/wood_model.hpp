#pragma once
// Everything needed to evaluate the wood at a point, built once from a project: the growth field
// (from the parameters and rates) and the material on top of it. Immutable, so many threads may
// evaluate it at once.
#include <memory>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "geometry/block.hpp"
#include "material/wood_material.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

struct Project;

class WoodModel {
 public:
  // Validates the parameters and the rates (InputError).
  // knots: the block's knots (Mokume Sec. 5.2.4), merged with the settings of the knots.* parameters.
  WoodModel(const Block& block, const WoodParameters& params, const GrowthRates& rates,
            const std::vector<BlockKnot>& knots = {});
  // A project's model: defined in io/project_wood_model.cpp, beside Project (render/ sits below io/).
  explicit WoodModel(const Project& project);
  WoodModel(const WoodModel&) = delete;
  WoodModel& operator=(const WoodModel&) = delete;

  const Block& block() const { return block_; }
  const WoodParameters& params() const { return *params_; }
  const GrowthField& field() const { return *field_; }
  const BlockKnots& knots() const { return *knots_; }
  const WoodMaterial& material() const { return *material_; }

  WoodSample evaluate(glm::vec3 pMm, int faceIndex = -1, bool withFiberDirection = false) const {
    return material_->evaluate(pMm, faceIndex, withFiberDirection);
  }

 private:
  Block block_;
  std::unique_ptr<const WoodParameters> params_;  // heap: the material keeps references
  std::unique_ptr<const GrowthField> field_;
  std::unique_ptr<const BlockKnots> knots_;
  std::unique_ptr<const WoodMaterial> material_;
};

}  // namespace kerf
