// Species presets (resources/presets/*.json): every Mokume Table 1 species present, every file valid,
// values inside the ranges, and applying a preset keeps the block-specific values.
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "io/preset_files.hpp"
#include "io/project.hpp"
#include "params/builtin_presets.hpp"
#include "params/presets.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kPresetDir = KERF_PRESETS_DIR;

fs::path scratch(const std::string& name) {
  return kerf::testing::scratchFolder("presets", name);
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string loadError(const fs::path& folder) {
  try {
    loadPresets(folder);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

json validPreset(const std::string& id) {
  return {{"format", "kerf-preset"},
          {"version", 1},
          {"id", id},
          {"name", "Test wood"},
          {"parameters", {{"growth.ring_width", 2.0}}}};
}

}  // namespace

TEST(Presets, EveryMokumeTable1SpeciesHasOnePreset) {
  // Mokume Table 1 (mokume-dataset-inverse-modeling-2025): 17 species codes.
  const std::set<std::string> table1 = {"B",  "BW", "CH", "CN", "H",  "IC", "K",  "KR", "MP",
                                        "MZ", "N",  "NR", "P",  "RO", "S",  "SG", "TC"};
  const auto presets = loadPresets(kPresetDir);
  std::set<std::string> codes, ids;
  for (const Preset& p : presets) {
    EXPECT_TRUE(codes.insert(p.mokumeCode).second) << "code " << p.mokumeCode << " twice";
    EXPECT_TRUE(ids.insert(p.id).second) << "id " << p.id << " twice";
    EXPECT_FALSE(p.latin.empty()) << p.id;
    EXPECT_FALSE(p.description.empty()) << p.id;
    EXPECT_EQ(p.description.find('\n'), std::string::npos) << p.id << ": description is one line";
  }
  EXPECT_EQ(codes, table1);
  EXPECT_EQ(presets.size(), table1.size());
}

TEST(Presets, SortedByName) {
  const auto presets = loadPresets(kPresetDir);
  ASSERT_FALSE(presets.empty());
  EXPECT_TRUE(std::is_sorted(presets.begin(), presets.end(),
                             [](const Preset& a, const Preset& b) { return a.name < b.name; }));
}

TEST(Presets, EveryValueIsValidNonDefaultAndOnTheSlider) {
  const WoodParameters defaults;
  const auto schema = parameterSchema();
  for (const Preset& preset : loadPresets(kPresetDir)) {
    SCOPED_TRACE(preset.id);
    // parametersFromJson refuses unknown ids, NaNs and values outside the hard ranges.
    WoodParameters params;
    ASSERT_NO_THROW(params = parametersFromJson(preset.parameters));
    EXPECT_NO_THROW(validate(params));
    EXPECT_FALSE(preset.parameters.empty());
    for (const auto& item : preset.parameters.items()) {
      const auto index = parameterIndex(item.key());
      ASSERT_TRUE(index) << item.key();
      const ParamSpec& spec = schema[*index];
      const auto values = params.components(*index);
      const auto defaultValues = defaults.components(*index);
      EXPECT_FALSE(std::equal(values.begin(), values.end(), defaultValues.begin()))
          << item.key() << " equals the schema default; leave it out";
      for (float v : values) {
        EXPECT_GE(v, spec.softMin) << item.key() << " below the slider's travel";
        EXPECT_LE(v, spec.softMax) << item.key() << " above the slider's travel";
      }
    }
  }
}

TEST(Presets, WoodAnatomyCategories) {
  const auto presets = loadPresets(kPresetDir);
  const auto byCode = [&](const std::string& code) {
    for (const Preset& p : presets) {
      if (p.mokumeCode == code) return p.parametersOnDefaults();
    }
    ADD_FAILURE() << "no preset " << code;
    return WoodParameters{};
  };
  // Softwoods (and ginkgo): no vessels.
  for (const char* code : {"H", "SG", "IC"}) {
    const WoodParameters p = byCode(code);
    EXPECT_EQ(p.poreDensityEarly, 0.0f) << code;
    EXPECT_EQ(p.poreDensityLate, 0.0f) << code;
  }
  // Ring-porous: earlywood pores much larger than latewood pores.
  for (const char* code : {"CN", "K", "N", "NR", "RO"}) {
    const WoodParameters p = byCode(code);
    EXPECT_GT(p.poreRadiusEarly, 3.0f * p.poreRadiusLate) << code;
    EXPECT_GE(p.poreRadiusEarly, 0.12f) << code;
  }
  // Diffuse-porous: small pores of about the same size through the ring.
  for (const char* code : {"B", "CH", "MP", "MZ", "P", "S", "TC"}) {
    const WoodParameters p = byCode(code);
    EXPECT_LE(p.poreRadiusEarly, 0.05f) << code;
    EXPECT_LE(p.poreRadiusEarly, 2.0f * p.poreRadiusLate) << code;
  }
  // Oaks have the broadest, tallest rays.
  for (const char* code : {"N", "RO"}) {
    const WoodParameters p = byCode(code);
    for (const Preset& other : presets) {
      if (other.mokumeCode == "N" || other.mokumeCode == "RO") continue;
      EXPECT_GT(p.rayHeight, other.parametersOnDefaults().rayHeight) << code << " vs " << other.id;
    }
  }
}

TEST(Presets, ApplyKeepsTheBlockSpecificValues) {
  const auto presets = loadPresets(kPresetDir);
  const Preset* nara = findPreset(presets, "nara");
  ASSERT_NE(nara, nullptr);
  WoodParameters base;
  base.seed = 777;
  base.pithOrigin = {3, 1, -20};
  base.pithTilt = 12;
  base.pithAzimuth = -40;
  base.ringOffset = 0.4f;
  base.eccentricity = 0.3f;
  base.faceTintC = {1.1f, 1.0f, 0.9f};
  base.rayWidth = 0.4f;  // a species value: replaced by the preset (or the default)
  base.mottleScale = 9;  // not in the preset: back to the default
  const WoodParameters applied = nara->applyTo(base);
  EXPECT_EQ(applied.seed, 777);
  EXPECT_EQ(applied.pithOrigin, base.pithOrigin);
  EXPECT_EQ(applied.pithTilt, 12);
  EXPECT_EQ(applied.pithAzimuth, -40);
  EXPECT_EQ(applied.ringOffset, 0.4f);
  EXPECT_EQ(applied.eccentricity, 0.3f);
  EXPECT_EQ(applied.faceTintC, base.faceTintC);
  EXPECT_EQ(applied.rayWidth, nara->parametersOnDefaults().rayWidth);
  EXPECT_EQ(applied.mottleScale, WoodParameters{}.mottleScale);
  EXPECT_EQ(applied.ringWidth, nara->parameters.at("growth.ring_width").get<float>());
  // Applying twice changes nothing more.
  EXPECT_EQ(nara->applyTo(applied), applied);
}

TEST(Presets, JsonRoundTrip) {
  for (const Preset& p : loadPresets(kPresetDir)) {
    const Preset again = presetFromJson(presetToJson(p));
    EXPECT_EQ(again.id, p.id);
    EXPECT_EQ(again.name, p.name);
    EXPECT_EQ(again.latin, p.latin);
    EXPECT_EQ(again.mokumeCode, p.mokumeCode);
    EXPECT_EQ(again.description, p.description);
    EXPECT_EQ(again.parameters, p.parameters);
  }
}

TEST(Presets, MalformedFilesAreRefusedNamingTheFile) {
  {
    const fs::path dir = scratch("bad_json");
    writeText(dir / "broken.json", "{\"format\": \"kerf-preset\", ");
    const std::string error = loadError(dir);
    EXPECT_NE(error.find("broken.json"), std::string::npos) << error;
    EXPECT_NE(error.find("not valid JSON"), std::string::npos) << error;
  }
  const auto expectError = [](const std::string& name, json doc, const std::string& fragment) {
    const fs::path dir = scratch(name);
    writeText(dir / (doc.value("id", std::string("x")) + ".json"), doc.dump());
    const std::string error = loadError(dir);
    EXPECT_NE(error.find(".json"), std::string::npos) << error;
    EXPECT_NE(error.find(fragment), std::string::npos) << name << ": " << error;
  };
  json doc = validPreset("wood");
  doc["format"] = "kerf-project";
  expectError("format", doc, "not a Kerf preset");
  doc = validPreset("wood");
  doc["version"] = 99;
  expectError("version", doc, "newer Kerf");
  doc = validPreset("wood");
  doc.erase("name");
  expectError("name", doc, "\"name\"");
  doc = validPreset("wood");
  doc["parameters"]["growth.ring_widht"] = 2.0;
  expectError("unknown_id", doc, "growth.ring_widht");
  doc = validPreset("wood");
  doc["parameters"]["rings.latewood_fraction"] = 1.5;
  expectError("range", doc, "rings.latewood_fraction");
  doc = validPreset("wood");
  doc["parameters"]["color.earlywood"] = {0.5, 0.5};
  expectError("vec3", doc, "color.earlywood");
  doc = validPreset("wood");
  doc["parameters"]["growth.pith_origin"] = {0, 0, 0};
  expectError("kept", doc, "growth.pith_origin");
  doc = validPreset("wood");
  doc["parameters"]["model.seed"] = 5;
  expectError("seed", doc, "model.seed");
  doc = validPreset("Wood Name");
  expectError("id_chars", doc, "lower-case");
  {
    const fs::path dir = scratch("id_mismatch");
    writeText(dir / "other.json", validPreset("wood").dump());
    EXPECT_NE(loadError(dir).find("must match the file name"), std::string::npos) << loadError(dir);
  }
  EXPECT_NE(loadError(scratch("x") / "missing").find("does not exist"), std::string::npos);
}

TEST(Presets, FolderWithValidPresetsLoads) {
  const fs::path dir = scratch("valid");
  json a = validPreset("b_wood");
  a["name"] = "Birch-like";
  json b = validPreset("a_wood");
  b["name"] = "Zebra-like";
  writeText(dir / "b_wood.json", a.dump());
  writeText(dir / "a_wood.json", b.dump());
  writeText(dir / "notes.txt", "ignored");
  const auto presets = loadPresets(dir);
  ASSERT_EQ(presets.size(), 2u);
  EXPECT_EQ(presets[0].name, "Birch-like");
  EXPECT_EQ(presets[1].name, "Zebra-like");
  EXPECT_EQ(findPreset(presets, "a_wood"), &presets[1]);
  EXPECT_EQ(findPreset(presets, "nope"), nullptr);
}

// The presets compiled into the core (params/builtin_presets.hpp) are the files, all of them.
TEST(Presets, BuiltInPresetsAreTheFiles) {
  const auto files = loadPresets(kPresetDir);
  const auto& builtIn = builtInPresets();
  ASSERT_EQ(builtIn.size(), files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    EXPECT_EQ(builtIn[i].id, files[i].id);
    EXPECT_EQ(presetToJson(builtIn[i]), presetToJson(files[i]));
  }
}

// Mokume samples are named by their species code and a number (Table 1): CN03 is chestnut (kuri).
TEST(Presets, SpeciesOfAMokumeSampleFromItsName) {
  ASSERT_NE(builtInPresetForSampleName("CN03"), nullptr);
  EXPECT_EQ(builtInPresetForSampleName("CN03")->id, "kuri");
  EXPECT_EQ(builtInPresetForSampleName("h11")->id, "hinoki");
  EXPECT_EQ(builtInPresetForSampleName("BW2")->id, "black_walnut");
  EXPECT_EQ(builtInPresetForSampleName("CN"), nullptr);    // no number: not a sample name
  EXPECT_EQ(builtInPresetForSampleName("XY03"), nullptr);  // no such species
  EXPECT_EQ(builtInPresetForSampleName("my_block"), nullptr);
  EXPECT_EQ(builtInPresetForSampleName(""), nullptr);
}
