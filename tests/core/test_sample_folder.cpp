// Annotations in project files (round trip, optional key, malformed input) and the checks of a
// Mokume-style sample folder (unreadable files, sizes that disagree, non-square faces of a cube,
// cuboid blocks, annotation images read with the photos).
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/image.hpp"
#include "io/mokume_annotation_files.hpp"
#include "io/project.hpp"
#include "rings/annotations.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return kerf::testing::scratchFolder("sample_folder", name);
}

void writePhoto(const fs::path& path, int w, int h) {
  Image image(w, h, 3);
  for (float& v : image.pixels) v = 0.6f;
  writeImage(path, image);
}

// All six faces of a cube at `px` px, or of a cuboid at `pxPerMm`.
void writeFaces(const fs::path& dir, const Block& block, float pxPerMm) {
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size = block.faceImageSize(face, pxPerMm);
    writePhoto(dir / (std::string(1, faceLetter(face)) + "_col.png"), size.x, size.y);
  }
}

std::string folderError(const fs::path& dir) {
  try {
    loadDocument(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string projectError(const std::string& annotations) {
  const std::string text = R"({"format": "kerf-project", "version": 1, "annotations": )" + annotations + "}";
  try {
    projectFromJson(nlohmann::json::parse(text), "/tmp");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Annotations someAnnotations() {
  Annotations a;
  a.traces.push_back({FaceId::B, {{1.25f, 2.5f}, {10.125f, 3.0f}, {20.0f, 7.75f}}, 4, TraceOrigin::Drawn});
  a.traces.push_back({FaceId::E, {{0.0f, 0.0f}, {40.0f, 40.0f}}, std::nullopt, TraceOrigin::Detected});
  a.knots = {{0, FaceId::C, {12.3f, 30.1f}}, {0, FaceId::F, {25.0f, 8.0f}}, {1, FaceId::A, {1.0f, 1.0f}}};
  return a;
}

}  // namespace

TEST(ProjectAnnotations, RoundTripThroughAProjectFile) {
  const fs::path dir = scratch("project");
  Project project;
  project.annotations = someAnnotations();
  saveProject(project, dir / "p.kerf");
  const Project back = loadProject(dir / "p.kerf");
  EXPECT_EQ(back.annotations, project.annotations);

  // No annotations: no key, and a file without the key (format 1 as before) loads with none.
  const nlohmann::json plain = projectToJson(Project(), dir);
  EXPECT_FALSE(plain.contains("annotations"));
  EXPECT_TRUE(projectFromJson(plain, dir).annotations.empty());
}

TEST(ProjectAnnotations, MalformedAnnotationsNameTheField) {
  EXPECT_NE(projectError("[1, 2]").find("\"annotations\" must be an object"), std::string::npos);
  EXPECT_NE(projectError(R"({"traces": 3})").find("annotations.traces must be a list"), std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "G", "points": [[1, 1], [2, 2]]}]})")
                .find("annotations.traces[0].face"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "A", "points": [[1, 1], [2]]}]})")
                .find("annotations.traces[0].points[1] must be [u, v]"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "A", "points": [[1, 1]]}]})").find("at least 2 points"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "A", "points": [[1, 1], [2, 99]]}]})")
                .find("annotations.traces[0].points[1] = [2,99] lies far outside face A"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "A", "points": [[1, 1], [2, 2]], "year": 2.5}]})")
                .find("annotations.traces[0].year must be a whole number"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"traces": [{"face": "A", "points": [[1, 1], [2, 2]], "origin": "guess"}]})")
                .find("annotations.traces[0].origin"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"knots": [{"knot": -1, "face": "A", "point": [1, 1]}]})")
                .find("annotations.knots[0].knot must be a whole number"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"knots": [{"face": "A"}]})").find("annotations.knots[0] must be"),
            std::string::npos);
  EXPECT_NE(projectError(R"({"lines": []})").find("unknown key annotations.lines"), std::string::npos);

  // Through a file, the message also names the project.
  const fs::path dir = scratch("malformed");
  std::ofstream(dir / "bad.kerf")
      << R"({"format": "kerf-project", "version": 1, "annotations": {"knots": [{"face": "Q", "point": [1, 1]}]}})";
  try {
    loadProject(dir / "bad.kerf");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.kerf"), std::string::npos) << m;
    EXPECT_NE(m.find("annotations.knots[0].face"), std::string::npos) << m;
  }
}

TEST(SampleFolder, ReadsAnnotationImagesWithThePhotos) {
  const fs::path dir = scratch("with_annotations");
  const Block block;
  writeFaces(dir, block, 6.4f);  // 256 px
  Annotations a;
  a.traces.push_back({FaceId::B, {{5, 5}, {35, 20}}, 6, TraceOrigin::Drawn});
  a.knots = {{0, FaceId::C, {12.0f, 30.0f}}, {0, FaceId::F, {25.0f, 8.0f}}};
  std::array<glm::ivec2, 6> sizes;
  sizes.fill({256, 256});
  writeMokumeAnnotations(a, block, dir, sizes);
  const Project project = loadDocument(dir);
  ASSERT_EQ(project.annotations.traces.size(), 1u);
  EXPECT_EQ(project.annotations.traces[0].year, 6);
  EXPECT_EQ(project.annotations.traces[0].face, FaceId::B);
  ASSERT_EQ(project.annotations.knots.size(), 2u);
  EXPECT_EQ(project.annotations.knots[0].face, FaceId::C);
  EXPECT_EQ(project.annotations.knots[1].face, FaceId::F);
  EXPECT_EQ(project.annotations.knots[1].knot, 0);
}

TEST(SampleFolder, BadInputGetsAMessageNamingTheFile) {
  // No faces.
  EXPECT_NE(folderError(scratch("empty")).find("holds no face photos"), std::string::npos);

  // An unreadable photo.
  {
    const fs::path dir = scratch("unreadable");
    writeFaces(dir, Block(), 0.8f);
    std::ofstream(dir / "C_col.png") << "not an image";
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("cannot read image "), std::string::npos) << m;
    EXPECT_NE(m.find("C_col.png"), std::string::npos) << m;
    EXPECT_NE(m.find("(the photo of face C)"), std::string::npos) << m;
  }
  // A non-square face for a cube.
  {
    const fs::path dir = scratch("not_square");
    writePhoto(dir / "A_col.png", 32, 24);
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("A_col.png is 32 x 24 px, not square, but the block is a 40 mm cube"), std::string::npos)
        << m;
    EXPECT_NE(m.find("block.json"), std::string::npos) << m;
  }
  // Faces of different sizes along a shared axis (opposite faces A and F).
  {
    const fs::path dir = scratch("different_sizes");
    writePhoto(dir / "A_col.png", 32, 32);
    writePhoto(dir / "F_col.png", 48, 48);
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("F_col.png is 48 x 48 px but A_col.png is 32 x 32 px"), std::string::npos) << m;
    EXPECT_NE(m.find("share the block's x axis"), std::string::npos) << m;
  }
  // Shared edge of neighbours: B (x by z) against C (z by y).
  {
    const fs::path dir = scratch("shared_edge");
    writePhoto(dir / "B_col.png", 32, 32);
    writePhoto(dir / "C_col.png", 40, 40);
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("C_col.png is 40 x 40 px but B_col.png is 32 x 32 px"), std::string::npos) << m;
    EXPECT_NE(m.find("z axis"), std::string::npos) << m;
  }
  // An annotation image of the wrong size.
  {
    const fs::path dir = scratch("annotation_size");
    writeFaces(dir, Block(), 0.8f);  // 32 px
    writePhoto(dir / "D_ann.png", 40, 20);
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("D_ann.png is 40 x 20 px but the photo D_col.png is 32 x 32 px"), std::string::npos)
        << m;
  }
  // An unreadable knot image.
  {
    const fs::path dir = scratch("knot_unreadable");
    writeFaces(dir, Block(), 0.8f);
    std::ofstream(dir / "E_knot.png") << "garbage";
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("E_knot.png: "), std::string::npos) << m;
    EXPECT_NE(m.find("(the annotation image of face E)"), std::string::npos) << m;
  }
  // A malformed block.json.
  {
    const fs::path dir = scratch("bad_block");
    writeFaces(dir, Block(), 0.8f);
    std::ofstream(dir / "block.json") << R"({"size_mm": [40, 0, 20]})";
    const std::string m = folderError(dir);
    EXPECT_NE(m.find("block.json"), std::string::npos) << m;
    EXPECT_NE(m.find("three positive lengths"), std::string::npos) << m;
  }
}

TEST(SampleFolder, CuboidBlocksFromBlockJson) {
  const fs::path dir = scratch("cuboid");
  const Block block(glm::vec3(40, 60, 20));
  writeFaces(dir, block, 2.0f);  // A 80 x 120, B 80 x 40, C 40 x 120 ...
  std::ofstream(dir / "block.json") << R"({"size_mm": [40, 60, 20]})";
  const Project project = loadDocument(dir);
  EXPECT_EQ(project.block.size(), glm::vec3(40, 60, 20));
  for (FaceId face : kAllFaces) EXPECT_FALSE(project.facePhotos[faceIndex(face)].empty());

  // The same photos without block.json: not a cube.
  fs::remove(dir / "block.json");
  EXPECT_NE(folderError(dir).find("not square"), std::string::npos);

  // A given block size wins over block.json; proportions that disagree name the face.
  std::ofstream(dir / "block.json") << R"({"size_mm": [40, 60, 20]})";
  try {
    projectFromSampleFolder(dir, glm::vec3(40, 40, 20));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "A_col.png is 80 x 120 px but face A of the 40 x 40 x 20 mm block is 40 x 40 mm"),
              std::string::npos)
        << e.what();
  }
}
