#include "params/parameter_schema.hpp"

#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>
#include <vector>

#include "util/error.hpp"

namespace kerf {
namespace {

// The words of the schema's attribute columns (wood_parameters.def), as values. Only this file reads
// those columns, so the short names stay here.
namespace columns {
constexpr ParamScale Linear = ParamScale::Linear, Log = ParamScale::Log;
constexpr ParamScope Species = ParamScope::Species, Block = ParamScope::Block;
constexpr GpuUse Uniform = GpuUse::Uniform, CpuOnly = GpuUse::CpuOnly;
constexpr unsigned NoFit = 0, Rings = unsigned(FitBy::Rings), Colour = unsigned(FitBy::Colour),
                   Texture = unsigned(FitBy::Texture);
constexpr SearchRange NoSearch{};
constexpr SearchRange Search(ParamScale scale, float lo, float hi) {
  return {true, scale, lo, hi};
}
}  // namespace columns

#define V1(a) \
  { float(a), 0.0f, 0.0f }
#define V3(a, b, c) \
  { float(a), float(b), float(c) }
using namespace columns;
const ParamSpec kSchema[] = {
// clang-format off
#define KERF_PARAM(name, id, group, label, unit, kind, def, smin, smax, hmin, hmax, scale, scope, fits, \
                   search, gpu, tip)                                                                    \
  {#name, id, group, label, unit, ParamKind::kind, def, smin, smax, hmin, hmax, scale, scope, fits, search, gpu, tip},
// clang-format on
#include "params/wood_parameters.def"
#undef KERF_PARAM
};
#undef V1
#undef V3

const ParamGroup kGroups[] = {
#define KERF_GROUP(id, title) {id, title},
#define KERF_PARAM(...)
#include "params/wood_parameters.def"
#undef KERF_PARAM
#undef KERF_GROUP
};

float* componentPointer(float& value) {
  return &value;
}
float* componentPointer(glm::vec3& value) {
  return glm::value_ptr(value);
}

}  // namespace

std::string_view paramKindName(ParamKind kind) {
  switch (kind) {
    case ParamKind::Scalar:
      return "scalar";
    case ParamKind::Integer:
      return "integer";
    case ParamKind::Color:
      return "color";
    case ParamKind::Vector3:
      return "vector3";
  }
  return "scalar";
}

std::span<const ParamSpec> parameterSchema() {
  return kSchema;
}

std::optional<std::size_t> parameterIndex(std::string_view id) {
  for (std::size_t i = 0; i < std::size(kSchema); ++i) {
    if (kSchema[i].id == id) return i;
  }
  return std::nullopt;
}

const ParamSpec* findParameter(std::string_view id) {
  const auto index = parameterIndex(id);
  return index ? &kSchema[*index] : nullptr;
}

std::span<const ParamGroup> parameterGroups() {
  return kGroups;
}

std::string_view parameterGroupTitle(std::string_view group) {
  for (const ParamGroup& g : kGroups)
    if (g.id == group) return g.title;
  return {};
}

std::string_view fitName(FitBy fit) {
  switch (fit) {
    case FitBy::Rings:
      return "rings";
    case FitBy::Colour:
      return "colour";
    case FitBy::Texture:
      return "texture";
  }
  return "";
}

std::span<float> WoodParameters::components(std::size_t index) {
  std::size_t i = 0;
#define KERF_PARAM(name, ...) \
  if (i++ == index) return {componentPointer(name), static_cast<std::size_t>(kSchema[index].components())};
#include "params/wood_parameters.def"
#undef KERF_PARAM
  throw std::out_of_range("parameter index out of range");
}

std::span<const float> WoodParameters::components(std::size_t index) const {
  const auto values = const_cast<WoodParameters*>(this)->components(index);
  return {values.data(), values.size()};
}

void validate(const WoodParameters& params) {
  const auto schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const ParamSpec& spec = schema[i];
    for (float v : params.components(i)) {
      if (!std::isfinite(v)) {
        throw InputError("parameter " + std::string(spec.id) + " is not a finite number");
      }
      if (v < spec.hardMin || v > spec.hardMax) {
        std::ostringstream message;
        message << "parameter " << spec.id << " = " << v << " is outside its allowed range [" << spec.hardMin
                << ", " << spec.hardMax << "]" << (spec.unit.empty() ? "" : " ") << spec.unit;
        throw InputError(message.str());
      }
      if (spec.kind == ParamKind::Integer && v != std::floor(v)) {
        throw InputError("parameter " + std::string(spec.id) + " must be a whole number");
      }
    }
  }
}

std::string glslUniformDeclarations() {
  std::ostringstream out;
  out << "// Generated from core/params/wood_parameters.def: the struct WoodParameters of the C++ core.\n"
      << "struct WoodParameters {\n";
  for (const ParamSpec& spec : parameterSchema()) {
    if (spec.gpu != GpuUse::Uniform) continue;
    out << "  " << (spec.components() == 3 ? "vec3" : "float") << " " << spec.name << ";  // " << spec.id
        << (spec.unit.empty() ? "" : " [") << spec.unit << (spec.unit.empty() ? "" : "]") << "\n";
  }
  out << "};\nuniform WoodParameters " << kGlslParametersName << ";\n";
  return out.str();
}

std::string glslUniformName(const ParamSpec& spec) {
  return std::string(kGlslParametersName) + "." + std::string(spec.name);
}

}  // namespace kerf
