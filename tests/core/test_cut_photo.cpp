// The photo of a real cut (core/io/cut_photo.hpp): its place in the project file, the plane it belongs
// to, and its rectification onto the cut's rectangle, pixel for pixel where renderCut puts the model's cut.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

#include "io/cut_photo.hpp"
#include "io/project.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

CutPhoto somePhoto(const fs::path& file) {
  CutPhoto photo;
  photo.setup.source = file;
  photo.setup.corners = {glm::vec2(10.5f, 8.0f), glm::vec2(300.25f, 12.0f), glm::vec2(290.0f, 200.0f),
                         glm::vec2(14.0f, 210.0f)};
  photo.setup.rotationDegrees = 270;
  photo.setup.flip = true;
  photo.plane = {3.5f, 12.25f, -7.0f};
  return photo;
}

std::string readError(const nlohmann::json& json) {
  try {
    cutPhotoFromJson(json, "/base");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CutPhoto, ProjectRoundTripKeepsThePhotoRelativeAndItsAlignment) {
  const fs::path dir = kerf::testing::scratchFolder("cut_photo", "round_trip");
  Project project;
  project.cutPhoto = somePhoto(dir / "photos" / "sawn.jpg");
  saveProject(project, dir / "p.kerf");
  std::ifstream in(dir / "p.kerf");
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["cut_photo"]["photo"], "photos/sawn.jpg");
  const Project loaded = loadProject(dir / "p.kerf");
  ASSERT_TRUE(loaded.cutPhoto.has_value());
  EXPECT_EQ(*loaded.cutPhoto, *project.cutPhoto);

  Project none;
  saveProject(none, dir / "none.kerf");
  std::ifstream noneIn(dir / "none.kerf");
  EXPECT_FALSE(nlohmann::json::parse(noneIn).contains("cut_photo"));  // omitted when there is none
  EXPECT_FALSE(loadProject(dir / "none.kerf").cutPhoto.has_value());
}

TEST(CutPhoto, BadEntriesNameTheField) {
  nlohmann::json good = cutPhotoToJson(somePhoto("/base/a.png"), "/base");
  EXPECT_EQ(readError(good), "");
  auto without = [&](const std::string& key) {
    nlohmann::json j = good;
    j.erase(key);
    return j;
  };
  EXPECT_NE(readError(without("photo")).find("\"photo\""), std::string::npos);
  EXPECT_NE(readError(without("corners_px")).find("corners_px"), std::string::npos);
  nlohmann::json turned = good;
  turned["rotation_deg"] = 45;
  EXPECT_NE(readError(turned).find("quarter turn"), std::string::npos) << readError(turned);
  nlohmann::json mirror = good;
  mirror["mirror"] = "yes";
  EXPECT_NE(readError(mirror).find("cut_photo.mirror"), std::string::npos);
}

TEST(CutPhoto, BelongsToItsPlaneOnly) {
  const CutPhoto photo = somePhoto("a.png");
  EXPECT_TRUE(cutPhotoBelongsTo(photo, photo.plane));
  CutPlaneSetting nudged = photo.plane;
  nudged.offsetMm += 0.004f;  // a rounding, not a move
  EXPECT_TRUE(cutPhotoBelongsTo(photo, nudged));
  nudged.offsetMm += 0.5f;
  EXPECT_FALSE(cutPhotoBelongsTo(photo, nudged));
  CutPlaneSetting tilted = photo.plane;
  tilted.elevationDeg += 1.0f;
  EXPECT_FALSE(cutPhotoBelongsTo(photo, tilted));
}

TEST(CutPhoto, WholePhotoRectifiesOntoRenderCutsPixels) {
  // The model's own cut as the photo, framed whole: the rectified picture is renderCut's, pixel for pixel
  // (up to the bicubic warp's rounding), on a slanted plane whose cut is not a face.
  const Project project;
  const WoodModel model(project);
  CutPhoto cut;
  cut.plane = {2.0f, 20.0f, 10.0f};
  const float pxPerMm = 4.0f;
  const Image own = renderCut(model, cut.plane.plane(), pxPerMm);
  Image photo(own.width, own.height, 3);
  for (int y = 0; y < own.height; ++y)
    for (int x = 0; x < own.width; ++x)
      for (int c = 0; c < 3; ++c) photo.pixel(x, y)[c] = own.pixel(x, y)[c];
  cut.setup.corners = wholePhotoCorners({photo.width, photo.height});
  EXPECT_NEAR(cutPhotoPxPerMm(cut, {photo.width, photo.height}, model.block(), 4096), pxPerMm, 0.05f);
  const Image rectified = rectifyCutPhoto(photo, cut, model.block(), pxPerMm);
  ASSERT_EQ(rectified.width, own.width);
  ASSERT_EQ(rectified.height, own.height);
  double worst = 0;
  for (int y = 0; y < own.height; ++y)
    for (int x = 0; x < own.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(rectified.pixel(x, y)[c] - photo.pixel(x, y)[c])));
  EXPECT_LT(worst, 1e-3);
  // The cap on the picture's size lowers the resolution, never raises it.
  EXPECT_LT(cutPhotoPxPerMm(cut, {photo.width, photo.height}, model.block(), 64), pxPerMm);
  // A plane that misses the block is refused.
  cut.plane.offsetMm = 500.0f;
  EXPECT_THROW(rectifyCutPhoto(photo, cut, model.block(), pxPerMm), InputError);
}
