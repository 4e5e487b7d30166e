#pragma once
// Arguments shared by the commands that take a log (render-board, render-panel).
#include <string>

#include "field/log_model.hpp"
#include "params/parameter_schema.hpp"

namespace kerf::cli {

// "random:SEED" or a path (Kerf log file or Gran_1 folder). Throws InputError.
LogModel loadLogArgument(const std::string& text);
// --set id=value[,value...]: one parameter of the schema. Throws InputError.
void applySetting(WoodParameters& params, const std::string& setting);

}  // namespace kerf::cli
