// Project files: round trips, relative photo paths, versions, malformed input, atomic saves.
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <cmath>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/image.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return kerf::testing::scratchFolder("project", name);
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string loadError(const fs::path& path) {
  try {
    loadProject(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Project, RoundTripKeepsEverySchemaValueAndTheRates) {
  const fs::path dir = scratch("roundtrip");
  Project project;
  project.block = Block(glm::vec3(40, 30, 20));
  project.params.ringWidth = 1.75f;
  project.params.latewoodColor = {0.3f, 0.2f, 0.1f};
  project.params.pithOrigin = {1.5f, -2.0f, -80.0f};
  project.params.seed = 12345;
  project.rates = synthesizeGrowthRates(project.params, project.block);
  project.rates->at(1, 2, 3) = -0.5f;
  project.facePhotos[0] = dir / "photos" / "A_col.png";
  project.facePhotos[4] = dir / "E.jpg";
  project.cutPlane = CutPlaneSetting{2.5f, 30.0f, -15.0f};
  project.cutEnabled = true;
  saveProject(project, dir / "p.kerf");

  const Project loaded = loadProject(dir / "p.kerf");
  EXPECT_EQ(loaded.params, project.params);
  EXPECT_EQ(loaded.block.size(), project.block.size());
  ASSERT_TRUE(loaded.rates);
  EXPECT_EQ(loaded.rates->rates, project.rates->rates);
  EXPECT_EQ(loaded.facePhotos[0], project.facePhotos[0]);
  EXPECT_EQ(loaded.facePhotos[4], project.facePhotos[4]);
  EXPECT_TRUE(loaded.facePhotos[1].empty());
  ASSERT_TRUE(loaded.cutPlane);
  EXPECT_EQ(*loaded.cutPlane, *project.cutPlane);
  EXPECT_TRUE(loaded.cutEnabled);

  // Photo paths are stored relative to the project, so a moved folder still opens.
  std::ifstream in(dir / "p.kerf");
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["faces"]["A"]["photo"], "photos/A_col.png");
  EXPECT_EQ(json["version"], kProjectFormatVersion);
  fs::remove_all(dir.parent_path() / "moved");
  fs::rename(dir, dir.parent_path() / "moved");
  const Project moved = loadProject(dir.parent_path() / "moved" / "p.kerf");
  EXPECT_EQ(moved.facePhotos[0], dir.parent_path() / "moved" / "photos" / "A_col.png");
}

TEST(Project, RoundTripKeepsTheHeldOutFaces) {
  const fs::path dir = scratch("held-out");
  Project project;
  saveProject(project, dir / "none.kerf");
  std::ifstream none(dir / "none.kerf");
  EXPECT_FALSE(nlohmann::json::parse(none).contains("held_out_faces"));  // omitted when empty
  EXPECT_TRUE(loadProject(dir / "none.kerf").heldOutFaces.empty());

  project.heldOutFaces.insert(FaceId::E);
  project.heldOutFaces.insert(FaceId::A);
  saveProject(project, dir / "p.kerf");
  std::ifstream in(dir / "p.kerf");
  EXPECT_EQ(nlohmann::json::parse(in)["held_out_faces"], "AE");
  EXPECT_EQ(loadProject(dir / "p.kerf").heldOutFaces, project.heldOutFaces);

  writeText(dir / "lower.kerf", R"({"format": "kerf-project", "version": 1, "held_out_faces": "c"})");
  EXPECT_EQ(loadProject(dir / "lower.kerf").heldOutFaces.letters(), "C");
  writeText(dir / "bad.kerf", R"({"format": "kerf-project", "version": 1, "held_out_faces": "CG"})");
  EXPECT_NE(loadError(dir / "bad.kerf").find("held_out_faces: 'G'"), std::string::npos)
      << loadError(dir / "bad.kerf");
  writeText(dir / "number.kerf", R"({"format": "kerf-project", "version": 1, "held_out_faces": 3})");
  EXPECT_NE(loadError(dir / "number.kerf").find("string of face letters"), std::string::npos);
}

TEST(Project, SavingIsAtomicAndLeavesNoTemporaryFiles) {
  const fs::path dir = scratch("atomic");
  Project project;
  saveProject(project, dir / "p.kerf");
  project.params.ringWidth = 5.0f;
  saveProject(project, dir / "p.kerf");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "p.kerf");
  }
  EXPECT_EQ(files, 1);
  EXPECT_FLOAT_EQ(loadProject(dir / "p.kerf").params.ringWidth, 5.0f);
  EXPECT_THROW(saveProject(project, dir / "missing-folder" / "p.kerf"), InputError);
}

TEST(Project, MissingParametersTakeDefaults) {
  const fs::path dir = scratch("defaults");
  writeText(dir / "p.kerf",
            R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": 2}})");
  const Project project = loadProject(dir / "p.kerf");
  EXPECT_FLOAT_EQ(project.params.ringWidth, 2.0f);
  EXPECT_EQ(project.params.latewoodColor, WoodParameters{}.latewoodColor);
  EXPECT_FALSE(project.rates);
}

TEST(Project, ClearErrorsForBadFiles) {
  const fs::path dir = scratch("errors");
  EXPECT_NE(loadError(dir / "nope.kerf").find("not found"), std::string::npos);

  writeText(dir / "broken.kerf", R"({"format": "kerf-project", "version": 1,)");
  EXPECT_NE(loadError(dir / "broken.kerf").find("not valid JSON"), std::string::npos);

  writeText(dir / "other.kerf", R"({"hello": 1})");
  EXPECT_NE(loadError(dir / "other.kerf").find("not a Kerf project"), std::string::npos);

  writeText(dir / "newer.kerf", R"({"format": "kerf-project", "version": 99})");
  EXPECT_NE(loadError(dir / "newer.kerf").find("newer Kerf"), std::string::npos);

  writeText(dir / "nan.kerf",
            R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": null}})");
  EXPECT_NE(loadError(dir / "nan.kerf").find("growth.ring_width"), std::string::npos);

  writeText(dir / "range.kerf",
            R"({"format": "kerf-project", "version": 1, "parameters": {"rays.density": 7}})");
  EXPECT_NE(loadError(dir / "range.kerf").find("outside its allowed range"), std::string::npos);

  writeText(dir / "unknown.kerf",
            R"({"format": "kerf-project", "version": 1, "parameters": {"rings.wobble": 1}})");
  EXPECT_NE(loadError(dir / "unknown.kerf").find("unknown parameter"), std::string::npos);

  writeText(dir / "color.kerf",
            R"({"format": "kerf-project", "version": 1, "parameters": {"color.earlywood": [1, 2]}})");
  EXPECT_NE(loadError(dir / "color.kerf").find("3 numbers"), std::string::npos);

  writeText(dir / "block.kerf",
            R"({"format": "kerf-project", "version": 1, "block": {"size_mm": [0, 1, 1]}})");
  EXPECT_NE(loadError(dir / "block.kerf").find("block size"), std::string::npos);

  writeText(
      dir / "grid.kerf",
      R"({"format": "kerf-project", "version": 1, "growth_rates": {"heights": 1, "azimuths": 1, "radii": 2,
                "height_range_mm": [0, 1], "radius_range_mm": [0, 5], "rates": [1]}})");
  EXPECT_NE(loadError(dir / "grid.kerf").find("expected 2"), std::string::npos);

  writeText(dir / "face.kerf",
            R"({"format": "kerf-project", "version": 1, "faces": {"G": {"photo": "x.png"}}})");
  EXPECT_NE(loadError(dir / "face.kerf").find("unknown face"), std::string::npos);
}

TEST(Project, SampleFolderFindsFacePhotos) {
  const fs::path dir = scratch("sample");
  EXPECT_THROW(projectFromSampleFolder(dir), InputError);
  // The photos are read (their sizes are checked against each other), so they must be real images.
  Image photo(16, 16, 3);
  writeImage(dir / "A_col.png", photo);
  writeImage(dir / "D_col.jpg", photo);
  const Project project = loadDocument(dir);
  EXPECT_EQ(project.facePhotos[0].filename(), "A_col.png");
  EXPECT_EQ(project.facePhotos[3].filename(), "D_col.jpg");
  EXPECT_TRUE(project.facePhotos[1].empty());
  EXPECT_EQ(project.block.size(), glm::vec3(40.0f));
}
