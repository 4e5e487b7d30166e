// WoodModel's constructor from a Project (render/wood_model.hpp declares it): here, beside the Project
// type, because render/ may not include io/ (scripts/check-folder-graph.py).
#include "io/project.hpp"
#include "render/wood_model.hpp"

namespace kerf {

WoodModel::WoodModel(const Project& project)
    : WoodModel(project.block, project.params, project.effectiveRates(), project.knots) {}

}  // namespace kerf
