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
// How a slider (or a search coordinate) maps its travel onto the value: evenly, or evenly in log(value).
enum class ParamScale { Linear, Log };
// Species: a preset may set it. Block: it describes this block (pith, photo tints, seed); presets keep it.
enum class ParamScope { Species, Block };
// Whether the shaders read it from `uniform WoodParameters P` (and it is uploaded), or only the CPU.
enum class GpuUse { CpuOnly, Uniform };
// The fits that may change a parameter, as bits of ParamSpec::fits.
enum class FitBy : unsigned { Rings = 1, Colour = 2, Texture = 4 };
// The interval the texture fit searches, on its own scale (which may differ from the slider's: a pore
// radius slider must reach 0, its search is logarithmic from a small floor).
struct SearchRange {
  bool searched = false;
  ParamScale scale = ParamScale::Linear;
  float lo = 0, hi = 0;
};

struct ParamSpec {
  std::string_view name;  // C++ member / GLSL struct member, e.g. "ringWidth"
  std::string_view id;    // stable id in files and on the command line, e.g. "growth.ring_width"
  std::string_view group;
  std::string_view label;
  std::string_view unit;
  ParamKind kind;
  std::array<float, 3> defaultValue;  // components beyond `components()` are unused
  float softMin, softMax;             // slider travel
  float hardMin, hardMax;             // what a project may hold
  ParamScale scale;                   // slider mapping
  ParamScope scope;
  unsigned fits;  // FitBy bits
  SearchRange search;
  GpuUse gpu;
  std::string_view tooltip;

  int components() const { return (kind == ParamKind::Color || kind == ParamKind::Vector3) ? 3 : 1; }
  bool fittedBy(FitBy fit) const { return (fits & static_cast<unsigned>(fit)) != 0; }
  bool fittable() const { return fits != 0; }
};

// A section of the schema: its id ("pores") and the title the editor shows ("Pores (vessels)").
struct ParamGroup {
  std::string_view id;
  std::string_view title;
};

std::string_view paramKindName(ParamKind kind);

// Every parameter, in declaration order.
std::span<const ParamSpec> parameterSchema();
// Looks a parameter up by its id ("growth.ring_width"); nullptr when unknown.
const ParamSpec* findParameter(std::string_view id);
// Index of a parameter in parameterSchema(), or nothing.
std::optional<std::size_t> parameterIndex(std::string_view id);
// Every group, in declaration order, and one group's title (empty when unknown).
std::span<const ParamGroup> parameterGroups();
std::string_view parameterGroupTitle(std::string_view group);
// The name of a fit as `kerf-cli params` prints it: "rings", "colour", "texture".
std::string_view fitName(FitBy fit);

#define KERF_PARAM_TYPE_Scalar float
#define KERF_PARAM_TYPE_Integer float
#define KERF_PARAM_TYPE_Color glm::vec3
#define KERF_PARAM_TYPE_Vector3 glm::vec3

// One value of every parameter, initialised to the schema defaults.
struct WoodParameters {
#define V1(a) float(a)
#define V3(a, b, c) glm::vec3(a, b, c)
#define KERF_PARAM(name, id, group, label, unit, kind, def, ...) KERF_PARAM_TYPE_##kind name = def;
#include "params/wood_parameters.def"
#undef KERF_PARAM
#undef V1
#undef V3

  // The components of parameter `index` (schema order): 1 or 3 floats.
  std::span<float> components(std::size_t index);
  std::span<const float> components(std::size_t index) const;

  bool operator==(const WoodParameters&) const = default;
};

// The 1 or 3 floats of one parameter value (a member of WoodParameters or KnotSettings).
inline std::span<const float> valueComponents(const float& value) {
  return {&value, 1};
}
inline std::span<const float> valueComponents(const glm::vec3& value) {
  return {&value.x, 3};
}

// Checks every value is finite and inside its hard range; throws InputError naming the parameter.
void validate(const WoodParameters& params);

// The GLSL twin of WoodParameters, generated from the schema's GpuUse::Uniform parameters: "struct
// WoodParameters { float ringWidth; ... }; uniform WoodParameters P;". The model's kernels
// (core/model/kernels/*.glsl) read a parameter as P.ringWidth in the shaders and in C++ alike; a CpuOnly
// parameter exists only on the C++ side.
inline constexpr const char* kGlslParametersName = "P";
std::string glslUniformDeclarations();
// The uniform that holds one parameter in the shaders: "P.ringWidth".
std::string glslUniformName(const ParamSpec& spec);

}  // namespace kerf
