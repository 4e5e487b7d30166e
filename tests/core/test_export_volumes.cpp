// Volume export as OpenVDB (read back with OpenVDB and compared with the NRRD of the same volume and the
// growth field) and depth stacks (numbered PNGs + index, compared with the model below the face).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include "test_files.hpp"

#include <fstream>
#include <sstream>

#include "demo/demo_block.hpp"
#include "export/depth_stack.hpp"
#include "export/export_job.hpp"
#include "export/volume_export.hpp"
#include "io/nrrd_writer.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path artifact(const std::string& name) {
  return kerf::testing::artifactFile("export", name);
}

Project boxProject() {
  Project project = demoProject();
  project.block = Block(glm::vec3(40, 20, 30));
  return project;
}

openvdb::GridBase::Ptr readGrid(const fs::path& path, const std::string& name) {
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open();
  openvdb::GridBase::Ptr grid = file.readGrid(name);
  file.close();
  return grid;
}

template <typename T>
std::vector<T> readNrrdData(const fs::path& path, std::size_t count) {
  const NrrdHeader header = readNrrdHeader(path);
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.dataOffset));
  std::vector<T> data(count);
  in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(count * sizeof(T)));
  EXPECT_TRUE(in);
  return data;
}

}  // namespace

TEST(ExportVdb, GrowthGridMatchesTheNrrdAndTheField) {
  const Project project = boxProject();
  const WoodModel model(project);
  const fs::path vdb = artifact("growth.vdb"), nrrd = artifact("growth_same.nrrd");
  const VolumeExportResult result = exportVolume(model, VolumeQuantity::Growth, 16, vdb);
  exportVolume(model, VolumeQuantity::Growth, 16, nrrd);
  ASSERT_EQ(result.size, glm::ivec3(16, 8, 12));
  EXPECT_EQ(result.bytes, fs::file_size(vdb));

  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(readGrid(vdb, "growth"));
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->activeVoxelCount(), openvdb::Index64(16 * 8 * 12));
  const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
  EXPECT_EQ(box.min(), openvdb::Coord(0, 0, 0));
  EXPECT_EQ(box.max(), openvdb::Coord(15, 7, 11));
  EXPECT_EQ(grid->metaValue<std::string>("quantity"), "growth");
  EXPECT_FALSE(grid->metaValue<std::string>("ring_levels").empty());

  const std::vector<float> reference = readNrrdData<float>(nrrd, 16 * 8 * 12);
  auto accessor = grid->getConstAccessor();
  for (int z = 0; z < 12; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x)
        ASSERT_EQ(accessor.getValue(openvdb::Coord(x, y, z)), reference[(z * 8 + y) * 16 + x]) << x << y << z;
  // Voxel centres sit at the samples' block millimetres.
  const openvdb::Vec3d p = grid->transform().indexToWorld(openvdb::Coord(3, 5, 9));
  const glm::vec3 expected = glm::vec3(-18.75f, -8.75f, -13.75f) + 2.5f * glm::vec3(3, 5, 9);
  EXPECT_NEAR(p.x(), expected.x, 1e-5);
  EXPECT_NEAR(p.y(), expected.y, 1e-5);
  EXPECT_NEAR(p.z(), expected.z, 1e-5);
  EXPECT_FLOAT_EQ(accessor.getValue(openvdb::Coord(3, 5, 9)), model.material().year(expected));
}

TEST(ExportVdb, ColorGridMatchesTheNrrdBytes) {
  const Project project = boxProject();
  const WoodModel model(project);
  const fs::path vdb = artifact("color.vdb"), nrrd = artifact("color_same.nrrd");
  exportVolume(model, VolumeQuantity::Color, 8, vdb);
  exportVolume(model, VolumeQuantity::Color, 8, nrrd);
  auto grid = openvdb::gridPtrCast<openvdb::Vec3SGrid>(readGrid(vdb, "color"));
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->activeVoxelCount(), openvdb::Index64(8 * 4 * 6));
  const std::vector<std::uint8_t> bytes = readNrrdData<std::uint8_t>(nrrd, 8 * 4 * 6 * 3);
  auto accessor = grid->getConstAccessor();
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 8; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(accessor.getValue(openvdb::Coord(x, y, z))[c],
                      bytes[((z * 4 + y) * 8 + x) * 3 + c] / 255.0f,
                      1e-3f);  // stored as half
}

TEST(ExportVdb, UnknownVolumeExtensionIsAnError) {
  const Project project = demoProject();
  const WoodModel model(project);
  EXPECT_THROW(exportVolume(model, VolumeQuantity::Growth, 4, artifact("growth.raw")), InputError);
  EXPECT_THROW(exportVolume(model, VolumeQuantity::Growth, 4, artifact("missing-folder") / "g.vdb"),
               InputError);
  EXPECT_FALSE(fs::exists(artifact("growth.raw")));
}

TEST(DepthStack, ParsesFaceStepAndDepth) {
  const DepthStackOptions o = parseDepthStack("E,0.5,3");
  EXPECT_EQ(o.face, FaceId::E);
  EXPECT_FLOAT_EQ(o.stepMm, 0.5f);
  EXPECT_FLOAT_EQ(o.depthMm, 3.0f);
  for (const char* bad : {"G,1,2", "A,1", "A,0,2", "A,1,-1", "AB,1,2", ""})
    EXPECT_THROW(parseDepthStack(bad), InputError) << bad;
}

TEST(DepthStack, ImagesAreTheModelBelowTheFaceWithAnIndex) {
  const Project project = boxProject();
  const WoodModel model(project);
  const fs::path folder = artifact("stack");
  fs::remove_all(folder);
  DepthStackOptions options;
  options.face = FaceId::B;  // +y; 20 mm of wood behind it
  options.stepMm = 2.5f;
  options.depthMm = 6.0f;
  options.pxPerMm = 1.0f;
  options.samples = 1;
  const DepthStackResult result = exportDepthStack(model, options, folder);
  ASSERT_EQ(result.depthsMm, (std::vector<float>{0.0f, 2.5f, 5.0f}));
  ASSERT_EQ(result.files.size(), 3u);
  std::ifstream csv(folder / "depths.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_EQ(text.str(), "index,file,depth_mm\n0,B_000.png,0\n1,B_001.png,2.5\n2,B_002.png,5\n");
  EXPECT_TRUE(fs::exists(folder / "depths.json"));

  const glm::ivec2 size = model.block().faceImageSize(FaceId::B, 1.0f);
  for (int i = 0; i < 3; ++i) {
    auto in = OIIO::ImageInput::open(result.files[i].string());
    ASSERT_TRUE(in);
    ASSERT_EQ(in->spec().width, size.x);
    ASSERT_EQ(in->spec().height, size.y);
    EXPECT_NEAR(in->spec().get_float_attribute("XResolution"), 25.4f, 0.01f);
    std::vector<float> pixels(static_cast<std::size_t>(size.x) * size.y * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
    for (int y = 0; y < size.y; y += 3)
      for (int x = 0; x < size.x; x += 4) {
        const glm::vec3 p =
            model.block().pixelCenter(FaceId::B, x, y, size) - glm::vec3(0, result.depthsMm[i], 0);
        const glm::vec3 c = model.evaluate(p).color;
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(pixels[(static_cast<std::size_t>(y) * size.x + x) * 3 + k], c[k], 0.5f / 255 + 1e-5f);
      }
  }
}

TEST(DepthStack, DepthThroughTheBlockIsRefusedBeforeWriting) {
  const Project project = boxProject();
  const WoodModel model(project);
  const fs::path folder = artifact("stack-too-deep");
  fs::remove_all(folder);
  DepthStackOptions options;
  options.face = FaceId::B;
  options.stepMm = 5.0f;
  options.depthMm = 20.0f;  // the block is 20 mm along y
  try {
    exportDepthStack(model, options, folder);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the block"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder));
}
