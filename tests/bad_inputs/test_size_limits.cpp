// Resolutions too big for memory or disk (issue 8, "a bounded memory use for big inputs"): every
// resolution option of kerf-cli that sizes an image or a volume is refused at once, with the size asked
// for and the largest that would do, before the memory is taken (util/size_limits.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <regex>

#include "bad_input_files.hpp"
#include "geometry/block.hpp"
#include "io/project.hpp"
#include "refused_run.hpp"
#include "util/error.hpp"
#include "util/size_limits.hpp"

using namespace kerf;
using namespace kerf::bad;

namespace {

class SizeLimits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTestFolder("size_limits", "out");
    saveProject(Project(), project());  // a 40 mm cube
  }
  fs::path project() const { return dir_ / "block.kerf"; }
  std::string args(const std::string& text) const {
    std::string s = text;
    for (std::size_t at; (at = s.find("{p}")) != std::string::npos;) s.replace(at, 3, project().string());
    for (std::size_t at; (at = s.find("{out}")) != std::string::npos;)
      s.replace(at, 5, (dir_ / "out").string());
    return s;
  }
  // kerf-cli refuses, quickly and without taking the memory, with a message matching `problem`.
  void expectRefused(const std::string& arguments, const std::string& problem) {
    expectRefusedAtOnce(runCli(args(arguments)), problem, dir_ / "out");
  }
  fs::path dir_;
};

}  // namespace

TEST(ImageSizeLimit, UpTo120MegapixelsAnd65535PxASide) {
  EXPECT_NO_THROW(checkImageSize({10954, 10954}, "the image"));  // 119.99 MP
  EXPECT_NO_THROW(checkImageSize({65535, 1000}, "the image"));
  const std::string tooMany = errorOf([] { checkImageSize({10955, 10955}, "the image of face C", 100.0f); });
  EXPECT_NE(tooMany.find("the image of face C would be 10955 x 10955 px (120 megapixels); Kerf makes images "
                         "of up to 120 megapixels and 65535 px a side: use at most 99.99 px/mm"),
            std::string::npos)
      << tooMany;
  const std::string tooLong = errorOf([] { checkImageSize({65536, 10}, "the cut"); });
  EXPECT_NE(tooLong.find("the cut would be 65536 x 10 px"), std::string::npos) << tooLong;
  EXPECT_NE(tooLong.find(": lower the resolution"), std::string::npos) << tooLong;
  EXPECT_NE(errorOf([] { checkImageSize({0, 10}, "x"); }).find("at least one pixel"), std::string::npos);
}

TEST(ImageSizeLimit, PixelCountsSaturateInsteadOfOverflowing) {
  EXPECT_EQ(pixelsAlong(1e30), 2'000'000'000);
  EXPECT_EQ(pixelsAlong(-3.0), 1);
  EXPECT_EQ(pixelsAlong(std::nan("")), 1);
  EXPECT_EQ(pixelsAlong(640.0), 640);
  int longest = 0;
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size = Block(glm::vec3(kMaxBlockSideMm, 40, 40)).faceImageSize(face, 1e5f);
    longest = std::max({longest, size.x, size.y});
  }
  EXPECT_EQ(longest, 2'000'000'000);
  EXPECT_NE(errorOf([] { Block(glm::vec3(1e30f, 40, 40)); }).find("at most 100000 mm"), std::string::npos);
}

TEST(MemoryLimit, RefusesWhatTheMachineCannotHold) {
  const std::uint64_t usable = usableMemoryBytes();
  EXPECT_GT(usable, 256ull << 20);
  EXPECT_NO_THROW(checkMemoryNeed(64ull << 20, "a small job"));
  const std::string error = errorOf([&] { checkMemoryNeed(usable, "the test volume"); });
  EXPECT_NE(error.find("the test volume needs about "), std::string::npos) << error;
  EXPECT_NE(error.find(" of memory; this machine lets Kerf use "), std::string::npos) << error;
}

TEST_F(SizeLimits, FaceImagesAtAResolutionTooHigh) {
  // 40 mm at 400 px/mm: 16000 x 16000 px a face, 3 GB as float RGB each.
  const std::string problem =
      "the image of face A would be 16000 x 16000 px \\(256 megapixels\\); Kerf makes images of up to 120 "
      "megapixels and 65535 px a side: use at most 273.86 px/mm";
  expectRefused("render-faces {p} --out {out} --px-per-mm 400", problem);
  expectRefused("export {p} --face A --px-per-mm 400 --out {out}/a.tif", problem);
  expectRefused("export {p} --depth-stack A,1,2 --px-per-mm 400 --out {out}/stack", problem);
  // The resolution it suggests is accepted.
  EXPECT_NO_THROW(checkImageSize(Block().faceImageSize(FaceId::A, 273.86f), "face A"));
}

TEST_F(SizeLimits, CutImageAtAResolutionTooHigh) {
  expectRefused("render-cut {p} --plane 0,0,0,1,1,0 --px-per-mm 400 --out {out}/cut.png",
                "the image of the cut would be [0-9]+ x [0-9]+ px .*: use at most [0-9.]+ px/mm");
}

TEST_F(SizeLimits, BlockTooLargeForItsFaceImages) {
  Project huge;
  huge.block = Block(glm::vec3(kMaxBlockSideMm, 40.0f, 40.0f));  // a 100 m log
  saveProject(huge, project());
  expectRefused("render-faces {p} --out {out} --px-per-mm 1",
                "the image of face [A-F] would be (100000 x 40|40 x 100000) px");
}

TEST_F(SizeLimits, PartTextureTooLarge) {
  writeText(dir_ / "cube.obj",
            "v -5 -5 -5\nv 5 -5 -5\nv -5 5 -5\nv 5 5 -5\nv -5 -5 5\nv 5 -5 5\nv -5 5 5\nv 5 5 5\n"
            "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
  expectRefused(
      "export {p} --mesh " + (dir_ / "cube.obj").string() + " --texture-res 16384 --out {out}/part.glb",
      "the part's texture would be 16384 x 16384 px \\(268 megapixels\\)");
}

TEST_F(SizeLimits, RectifiedFaceTooLarge) {
  writePhoto(dir_ / "photo.png", 16, 16);
  expectRefused(
      "rectify " + (dir_ / "photo.png").string() +
          " --corners 0,0,15,0,15,15,0,15 --size-mm 100000,100000 --px-per-mm 200 --out {out}/face.png",
      "the face image would be 20000000 x 20000000 px");
}

TEST_F(SizeLimits, VdbVolumeTooLargeForMemory) {
  // 4096^3 float voxels: about 290 GB in OpenVDB's dense leaves.
  if (usableMemoryBytes() > (300ull << 30)) GTEST_SKIP() << "this machine could hold a 4096^3 VDB volume";
  expectRefused(
      "export {p} --res 4096 --out {out}/growth.vdb",
      "the 4096 x 4096 x 4096 VDB volume needs about [0-9]+ GiB of memory; this machine lets Kerf use "
      "[0-9.]+ GiB: lower the resolution");
}

TEST_F(SizeLimits, NrrdVolumeTooLargeForTheDisk) {
  // 4096^3 RGB voxels: 192 GiB, written slice by slice, so only the disk bounds it.
  const std::uint64_t bytes = 4096ull * 4096 * 4096 * 3;
  if (fs::space(dir_).available >= bytes)
    GTEST_SKIP() << "the disk has room for a 192 GiB volume; the refusal cannot be shown here";
  expectRefused("export {p} --res 4096 --quantity colour --out {out}/colour.nrrd",
                "the 4096 x 4096 x 4096 volume needs 192 GiB on disk; .* GiB free: lower the resolution");
}
