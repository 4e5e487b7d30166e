// The one parameter schema: consistent metadata, typed access, validation, GLSL declarations.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "params/parameter_schema.hpp"
#include "util/error.hpp"

using namespace kerf;

TEST(Schema, EveryParameterIsWellFormed) {
  const auto schema = parameterSchema();
  ASSERT_GE(schema.size(), 40u);
  std::set<std::string_view> ids, names;
  const std::set<std::string_view> groups{"growth", "rings", "color", "distortion", "fibers",
                                          "pores",  "rays",  "faces", "model",      "knots"};
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

TEST(Schema, GlslDeclaresTheParameterStructWithEveryParameter) {
  const std::string glsl = glslUniformDeclarations();
  EXPECT_NE(glsl.find("struct WoodParameters {"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("uniform WoodParameters P;"), std::string::npos) << glsl;
  for (const ParamSpec& spec : parameterSchema()) {
    const std::string member = std::string("  ") + (spec.components() == 3 ? "vec3" : "float") + " " +
                               std::string(spec.name) + ";";
    EXPECT_NE(glsl.find(member), std::string::npos) << member;
    EXPECT_EQ(glslUniformName(spec), "P." + std::string(spec.name));
  }
}
