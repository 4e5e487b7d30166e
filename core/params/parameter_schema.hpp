#pragma once
// The parameter schema (see wood_parameters.def): metadata of every procedural parameter, and the
// typed struct WoodParameters that holds one value of each. Both are generated from the .def table,
// so a parameter is added in exactly one place.
#include <array>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace kerf {

enum class ParamKind { Scalar, Integer, Color, Vector3 };

struct ParamSpec {
  std::string_view name;  // C++ member / GLSL uniform suffix, e.g. "ringWidth"
  std::string_view id;    // stable id in files and on the command line, e.g. "growth.ring_width"
  std::string_view group;
  std::string_view label;
  std::string_view unit;
  ParamKind kind;
  std::array<float, 3> defaultValue;  // components beyond `components()` are unused
  float softMin, softMax;             // slider travel
  float hardMin, hardMax;             // what a project may hold
  bool fittable;                      // whether fitting may change it
  std::string_view tooltip;

  int components() const { return (kind == ParamKind::Color || kind == ParamKind::Vector3) ? 3 : 1; }
};

std::string_view paramKindName(ParamKind kind);

// Every parameter, in declaration order.
std::span<const ParamSpec> parameterSchema();
// Looks a parameter up by its id ("growth.ring_width"); nullptr when unknown.
const ParamSpec* findParameter(std::string_view id);
// Index of a parameter in parameterSchema(), or nothing.
std::optional<std::size_t> parameterIndex(std::string_view id);

#define KERF_PARAM_TYPE_Scalar float
#define KERF_PARAM_TYPE_Integer float
#define KERF_PARAM_TYPE_Color glm::vec3
#define KERF_PARAM_TYPE_Vector3 glm::vec3

// One value of every parameter, initialised to the schema defaults.
struct WoodParameters {
#define V1(a) float(a)
#define V3(a, b, c) glm::vec3(a, b, c)
#define KERF_PARAM(name, id, group, label, unit, kind, def, smin, smax, hmin, hmax, fit, tip) \
  KERF_PARAM_TYPE_##kind name = def;
#include "params/wood_parameters.def"
#undef KERF_PARAM
#undef V1
#undef V3

  // The components of parameter `index` (schema order): 1 or 3 floats.
  std::span<float> components(std::size_t index);
  std::span<const float> components(std::size_t index) const;

  bool operator==(const WoodParameters&) const = default;
};

// Checks every value is finite and inside its hard range; throws InputError naming the parameter.
void validate(const WoodParameters& params);

// The GLSL twin of WoodParameters, generated from the schema: "struct WoodParameters { float ringWidth;
// ... }; uniform WoodParameters P;". The model's kernels (core/model/kernels/*.glsl) read a parameter as
// P.ringWidth in the shaders and in C++ alike.
inline constexpr const char* kGlslParametersName = "P";
std::string glslUniformDeclarations();
// The uniform that holds one parameter in the shaders: "P.ringWidth".
std::string glslUniformName(const ParamSpec& spec);

}  // namespace kerf
