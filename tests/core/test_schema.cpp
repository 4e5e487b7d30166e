// The one parameter schema: consistent metadata, typed access, validation, GLSL declarations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "field/knot_field.hpp"
#include "params/parameter_schema.hpp"
#include "params/presets.hpp"
#include "util/error.hpp"

using namespace kerf;

TEST(Schema, EveryParameterIsWellFormed) {
  const auto schema = parameterSchema();
  ASSERT_GE(schema.size(), 40u);
  std::set<std::string_view> ids, names;
  std::set<std::string_view> groups;
  for (const ParamGroup& group : parameterGroups()) groups.insert(group.id);
  for (const ParamSpec& spec : schema) {
    EXPECT_TRUE(ids.insert(spec.id).second) << "duplicate id " << spec.id;
    EXPECT_TRUE(names.insert(spec.name).second) << "duplicate name " << spec.name;
    EXPECT_EQ(spec.id.substr(0, spec.id.find('.')), spec.group) << spec.id << " must start with its group";
    EXPECT_TRUE(groups.count(spec.group)) << spec.id;
    EXPECT_FALSE(spec.label.empty()) << spec.id;
    EXPECT_GT(spec.tooltip.size(), 15u) << spec.id << " needs a tooltip that explains it";
    EXPECT_LE(spec.hardMin, spec.softMin) << spec.id;
    EXPECT_LT(spec.softMin, spec.softMax) << spec.id;
    EXPECT_LE(spec.softMax, spec.hardMax) << spec.id;
    for (int c = 0; c < spec.components(); ++c) {
      EXPECT_GE(spec.defaultValue[c], spec.hardMin) << spec.id;
      EXPECT_LE(spec.defaultValue[c], spec.hardMax) << spec.id;
    }
    EXPECT_EQ(findParameter(spec.id), &spec);
  }
  EXPECT_EQ(findParameter("no.such_parameter"), nullptr);
}

TEST(Schema, StructFieldsFollowTheSchemaOrder) {
  WoodParameters params;
  const auto index = parameterIndex("growth.ring_width");
  ASSERT_TRUE(index);
  params.components(*index)[0] = 4.25f;
  EXPECT_FLOAT_EQ(params.ringWidth, 4.25f);
  const auto color = parameterIndex("color.latewood");
  ASSERT_TRUE(color);
  ASSERT_EQ(params.components(*color).size(), 3u);
  params.components(*color)[2] = 0.125f;
  EXPECT_FLOAT_EQ(params.latewoodColor.z, 0.125f);
  // Defaults of the struct equal the schema defaults.
  const WoodParameters defaults;
  const auto schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i)
    for (int c = 0; c < schema[i].components(); ++c)
      EXPECT_FLOAT_EQ(defaults.components(i)[c], schema[i].defaultValue[c]) << schema[i].id;
}

TEST(Schema, ValidationNamesTheBadParameter) {
  WoodParameters params;
  EXPECT_NO_THROW(validate(params));
  params.ringWidth = std::nanf("");
  try {
    validate(params);
    FAIL() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("growth.ring_width"), std::string::npos) << e.what();
  }
  params = {};
  params.latewoodColor.y = 1.5f;
  EXPECT_THROW(validate(params), InputError);
  params = {};
  params.seed = 2.5f;
  EXPECT_THROW(validate(params), InputError);
}

TEST(Schema, GlslDeclaresTheStructWithEveryGpuParameterOnly) {
  const std::string glsl = glslUniformDeclarations();
  EXPECT_NE(glsl.find("struct WoodParameters {"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("uniform WoodParameters P;"), std::string::npos) << glsl;
  int uniforms = 0;
  for (const ParamSpec& spec : parameterSchema()) {
    const std::string member = std::string(" ") + std::string(spec.name) + ";";
    if (spec.gpu == GpuUse::Uniform) {
      ++uniforms;
      EXPECT_NE(glsl.find(std::string(" ") + (spec.components() == 3 ? "vec3" : "float") + member),
                std::string::npos)
          << member;
    } else {
      EXPECT_EQ(glsl.find(member), std::string::npos) << spec.id << " is CpuOnly but declared in GLSL";
    }
    EXPECT_EQ(glslUniformName(spec), "P." + std::string(spec.name));
  }
  EXPECT_GT(uniforms, 40);
}

// The attribute columns agree with each other (wood_parameters.def explains them).
TEST(Schema, AttributesAreConsistent) {
  for (const ParamSpec& spec : parameterSchema()) {
    SCOPED_TRACE(std::string(spec.id));
    // Defaults lie on the slider's travel, so a reset puts the handle on the track.
    for (int c = 0; c < spec.components(); ++c) {
      EXPECT_GE(spec.defaultValue[c], spec.softMin);
      EXPECT_LE(spec.defaultValue[c], spec.softMax);
    }
    if (spec.kind == ParamKind::Integer) {
      EXPECT_EQ(spec.defaultValue[0], std::floor(spec.defaultValue[0]));
      EXPECT_EQ(spec.fits, 0u) << "no fit changes a whole number";
    }
    if (spec.scale == ParamScale::Log) {
      EXPECT_EQ(spec.kind, ParamKind::Scalar) << "only a scalar has a slider";
      EXPECT_GT(spec.softMin, 0.0f) << "a log slider cannot reach 0";
    }
    EXPECT_EQ(spec.fits & ~7u, 0u) << "unknown fit bits";
    if (spec.search.searched) {
      EXPECT_TRUE(spec.fittedBy(FitBy::Texture)) << "searched by the texture fit, so it changes it";
      EXPECT_EQ(spec.kind, ParamKind::Scalar);
      EXPECT_LT(spec.search.lo, spec.search.hi);
      EXPECT_GE(spec.search.lo, spec.hardMin) << "the search may leave the slider, not the hard range";
      EXPECT_LE(spec.search.hi, spec.hardMax);
      if (spec.search.scale == ParamScale::Log) {
        EXPECT_GT(spec.search.lo, 0.0f);
      }
      // Where the search leaves the slider's travel it does so on purpose (pores.darkness, explained in
      // the .def); it always covers at least part of that travel.
      EXPECT_LT(spec.search.lo, spec.softMax);
      EXPECT_GT(spec.search.hi, spec.softMin);
    }
    EXPECT_FALSE(parameterGroupTitle(spec.group).empty());
  }
}

TEST(Schema, GroupsAreDeclaredOnceAndHoldContiguousParameters) {
  const auto schema = parameterSchema();
  std::set<std::string_view> ids;
  for (const ParamGroup& group : parameterGroups()) {
    EXPECT_TRUE(ids.insert(group.id).second) << "group declared twice: " << group.id;
    EXPECT_FALSE(group.title.empty()) << group.id;
    EXPECT_EQ(parameterGroupTitle(group.id), group.title);
  }
  EXPECT_TRUE(parameterGroupTitle("no_such_group").empty());
  // The editor shows one section per group: its parameters must follow each other.
  std::set<std::string_view> closed;
  for (std::size_t i = 0; i < schema.size(); ++i) {
    EXPECT_FALSE(closed.count(schema[i].group)) << schema[i].id << " is apart from its group";
    if (i + 1 < schema.size() && schema[i + 1].group != schema[i].group) closed.insert(schema[i].group);
  }
  for (const ParamGroup& group : parameterGroups())
    EXPECT_TRUE(
        std::any_of(schema.begin(), schema.end(), [&](const ParamSpec& s) { return s.group == group.id; }))
        << "empty group " << group.id;
}

TEST(Schema, PresetsKeepExactlyTheBlockScopedParameters) {
  std::set<std::string_view> block;
  for (const ParamSpec& spec : parameterSchema())
    if (spec.scope == ParamScope::Block) block.insert(spec.id);
  const auto kept = presetKeptParameterIds();
  EXPECT_EQ(std::set<std::string_view>(kept.begin(), kept.end()), block);
  EXPECT_TRUE(block.count("growth.pith_origin"));
  EXPECT_TRUE(block.count("model.seed"));
}

// KnotSettings is generated from the schema's knot lines: same names, same defaults, every one.
TEST(Schema, KnotSettingsAreTheKnotGroup) {
  const KnotSettings defaults;
  std::vector<std::string_view> visited;
  defaults.forEachParameter([&](const ParamSpec& spec, std::span<const float> value) {
    visited.push_back(spec.id);
    ASSERT_EQ(static_cast<int>(value.size()), spec.components()) << spec.id;
    for (int c = 0; c < spec.components(); ++c) EXPECT_EQ(value[c], spec.defaultValue[c]) << spec.id;
  });
  std::vector<std::string_view> knots;
  for (const ParamSpec& spec : parameterSchema())
    if (spec.group == "knots") knots.push_back(spec.id);
  EXPECT_EQ(visited, knots);

  // fromParameters copies every member: give each knot parameter a distinct value.
  WoodParameters params;
  const auto schema = parameterSchema();
  float next = 0.25f;
  for (std::size_t i = 0; i < schema.size(); ++i)
    if (schema[i].group == "knots")
      for (float& v : params.components(i)) v = (next += 0.125f);
  const KnotSettings copied = KnotSettings::fromParameters(params);
  copied.forEachParameter([&](const ParamSpec& spec, std::span<const float> value) {
    const auto from = params.components(*parameterIndex(spec.id));
    EXPECT_TRUE(std::equal(value.begin(), value.end(), from.begin(), from.end())) << spec.id;
  });
}
