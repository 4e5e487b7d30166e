#pragma once
// Multithreaded evaluation of the model at many points at once (fitting losses, exporters, tests):
// the points are split into chunks spread over the worker threads (util/parallel.hpp).
#include <glm/vec3.hpp>
#include <span>

#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

// years[i] = growth time at points[i] (WoodMaterial::year). Spans must have equal sizes.
void evaluateYears(const WoodModel& model, std::span<const glm::vec3> points, std::span<float> years,
                   const Progress& progress = {});

// colors[i] = colour at points[i] (no face tint). Spans must have equal sizes.
void evaluateColors(const WoodModel& model, std::span<const glm::vec3> points, std::span<glm::vec3> colors,
                    const Progress& progress = {});

}  // namespace kerf
