// params: the parameter schema (or, with --presets, the built-in species) as JSON.
#include <iostream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "params/builtin_presets.hpp"
#include "params/parameter_schema.hpp"

namespace kerf::cli {
namespace {

const char* scaleName(ParamScale scale) {
  return scale == ParamScale::Log ? "log" : "linear";
}

}  // namespace

Command addParamsCommand(CLI::App& app) {
  auto* params = app.add_subcommand("params", "Print the parameter schema as JSON");
  auto presets = std::make_shared<bool>(false);
  params->add_flag("--presets", *presets,
                   "Print the built-in species presets instead (id, name, Mokume code)");
  return {params, [presets](Context&) {
            if (*presets) {
              nlohmann::ordered_json out = nlohmann::ordered_json::array();
              for (const Preset& preset : builtInPresets())
                out.push_back({{"id", preset.id},
                               {"name", preset.name},
                               {"latin", preset.latin},
                               {"mokume_code", preset.mokumeCode},
                               {"description", preset.description}});
              std::cout << out.dump(2) << "\n";
              return;
            }
            nlohmann::ordered_json out = nlohmann::ordered_json::array();
            for (const ParamSpec& spec : parameterSchema()) {
              nlohmann::ordered_json def =
                  spec.components() == 1
                      ? nlohmann::ordered_json(spec.defaultValue[0])
                      : nlohmann::ordered_json::array(
                            {spec.defaultValue[0], spec.defaultValue[1], spec.defaultValue[2]});
              nlohmann::ordered_json fits = nlohmann::ordered_json::array();
              for (const FitBy fit : {FitBy::Rings, FitBy::Colour, FitBy::Texture})
                if (spec.fittedBy(fit)) fits.push_back(fitName(fit));
              nlohmann::ordered_json entry = {
                  {"id", spec.id},
                  {"group", spec.group},
                  {"group_title", parameterGroupTitle(spec.group)},
                  {"label", spec.label},
                  {"unit", spec.unit},
                  {"kind", paramKindName(spec.kind)},
                  {"default", def},
                  {"soft_range", {spec.softMin, spec.softMax}},
                  {"hard_range", {spec.hardMin, spec.hardMax}},
                  {"scale", scaleName(spec.scale)},
                  {"scope", spec.scope == ParamScope::Block ? "block" : "species"},
                  {"fittable", spec.fittable()},
                  {"fits", fits}};
              if (spec.search.searched)
                entry["texture_search"] = {{"scale", scaleName(spec.search.scale)},
                                           {"range", {spec.search.lo, spec.search.hi}}};
              entry["glsl_uniform"] =
                  spec.gpu == GpuUse::Uniform ? nlohmann::ordered_json(glslUniformName(spec)) : nullptr;
              entry["tooltip"] = spec.tooltip;
              out.push_back(std::move(entry));
            }
            std::cout << out.dump(2) << "\n";
          }};
}

}  // namespace kerf::cli
