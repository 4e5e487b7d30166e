// NRRD volume export: header (sizes, spacing, origin in mm, ring levels), data, streaming, cancel.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "demo/demo_block.hpp"
#include "export/volume_export.hpp"
#include "io/nrrd_writer.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {
fs::path artifact(const std::string& name) {
  return fs::path(KERF_TEST_ARTIFACTS) / name;
}
}  // namespace

TEST(Volume, GrowthVolumeHeaderAndData) {
  Project project = demoProject();
  project.block = Block(glm::vec3(40, 20, 30));
  const WoodModel model(project);
  const fs::path path = artifact("growth.nrrd");
  const VolumeExportResult result = exportVolume(model, VolumeQuantity::Growth, 16, path);
  EXPECT_EQ(result.size, glm::ivec3(16, 8, 12));

  const NrrdHeader header = readNrrdHeader(path);
  EXPECT_EQ(header.field("type"), "float");
  EXPECT_EQ(header.field("sizes"), "16 8 12");
  EXPECT_EQ(header.field("space directions"), "(2.5,0,0) (0,2.5,0) (0,0,2.5)");
  EXPECT_EQ(header.field("space origin"), "(-18.75,-8.75,-13.75)");
  EXPECT_EQ(header.field("endian"), "little");
  EXPECT_EQ(header.keyValue("quantity"), "growth");

  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.dataOffset));
  std::vector<float> data(16 * 8 * 12);
  in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * 4));
  ASSERT_TRUE(in) << "volume data is shorter than its header says";
  EXPECT_EQ(in.peek(), EOF);
  // x fastest, then y, then z; samples at voxel centres.
  for (glm::ivec3 v : {glm::ivec3(0, 0, 0), glm::ivec3(15, 7, 11), glm::ivec3(3, 5, 9)}) {
    const glm::vec3 p = glm::vec3(-18.75f, -8.75f, -13.75f) + 2.5f * glm::vec3(v);
    EXPECT_FLOAT_EQ(data[(v.z * 8 + v.y) * 16 + v.x], model.material().year(p));
  }

  // ring_levels: whole years (+ ring offset) covering every value in the volume.
  std::istringstream levels(header.keyValue("ring_levels"));
  std::vector<float> ring;
  for (float v; levels >> v;) ring.push_back(v);
  ASSERT_GE(ring.size(), 3u);
  for (std::size_t i = 1; i < ring.size(); ++i) EXPECT_NEAR(ring[i] - ring[i - 1], 1.0f, 1e-4f);
  const auto [lo, hi] = std::minmax_element(data.begin(), data.end());
  EXPECT_LE(ring.front(), *lo);
  EXPECT_GE(ring.back(), *hi);
}

TEST(Volume, ColorVolumeIsRgbBytes) {
  const WoodModel model(demoProject());
  const fs::path path = artifact("color.nrrd");
  exportVolume(model, VolumeQuantity::Color, 8, path);
  const NrrdHeader header = readNrrdHeader(path);
  EXPECT_EQ(header.field("type"), "uint8");
  EXPECT_EQ(header.field("sizes"), "3 8 8 8");
  EXPECT_EQ(header.field("kinds"), "RGB-color domain domain domain");
  EXPECT_EQ(fs::file_size(path), header.dataOffset + 3 * 8 * 8 * 8);
}

TEST(Volume, CancelLeavesNoFileAndBadInputIsRefused) {
  const WoodModel model(demoProject());
  const fs::path path = artifact("cancelled.nrrd");
  fs::remove(path);
  std::stop_source stop;
  stop.request_stop();
  EXPECT_THROW(exportVolume(model, VolumeQuantity::Growth, 32, path, {nullptr, stop.get_token()}), Cancelled);
  EXPECT_FALSE(fs::exists(path));
  for (const auto& entry : fs::directory_iterator(path.parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".cancelled.nrrd.tmp"), std::string::npos);
  EXPECT_THROW(exportVolume(model, VolumeQuantity::Growth, 0, path), InputError);
  EXPECT_THROW(volumeQuantityFromName("density"), InputError);
  EXPECT_THROW(exportVolume(model, VolumeQuantity::Growth, 4, artifact("no/such/folder/v.nrrd")), InputError);
}
