// Which libraries an image needs (io/oiio_codecs.hpp): PNG and BMP are read and written without
// OpenImageIO, whose 260 libraries took 0.3 s of every kerf-cli start; the first TIFF loads it, and it
// works. A program of its own, which does not link OpenImageIO, so that nothing else has loaded it.
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <fstream>
#include <string>

#include "io/image.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

bool openImageIOIsLoaded() {
  std::ifstream maps("/proc/self/maps");
  EXPECT_TRUE(maps) << "cannot read /proc/self/maps";
  const std::string all((std::istreambuf_iterator<char>(maps)), {});
  EXPECT_NE(all.find("libc.so"), std::string::npos) << "the map lists no libraries";
  return all.find("libOpenImageIO") != std::string::npos;
}

// A 2 x 2 24-bit BMP, bottom row first, BGR, rows padded to 4 bytes.
void writeBmp(const fs::path& path) {
  const unsigned char bytes[] = {
      'B', 'M', 70,  0,   0,   0,   0,   0, 0, 0, 54, 0, 0, 0,  // file header: size, data at 54
      40,  0,   0,   0,   2,   0,   0,   0, 2, 0, 0,  0, 1, 0,
      24,  0,   0,   0,   0,   0,   16,  0, 0, 0,  // info: 2 x 2, 24 bits
      0,   0,   0,   0,   0,   0,   0,   0, 0, 0, 0,  0, 0, 0,
      0,   0,   255, 0,   0,   0,   255, 0, 0, 0,  // bottom row: blue, green
      0,   0,   255, 255, 255, 255, 0,   0,        // top row: red, white
  };
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes), sizeof bytes);
}

}  // namespace

TEST(ImageLoading, PngAndBmpNeedNoOpenImageIOTheFirstTiffLoadsIt) {
  const fs::path dir = kerf::testing::scratchFolder("codecs", "loading");
  ASSERT_FALSE(openImageIOIsLoaded());

  Image image(3, 2, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<float>(i) / 17.0f;
  writeImage(dir / "a.png", image);
  const Image png = readImage(dir / "a.png");
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    EXPECT_NEAR(png.pixels[i], image.pixels[i], 0.5f / 255.0f);

  writeBmp(dir / "b.bmp");
  const Image bmp = readImage(dir / "b.bmp");
  ASSERT_EQ(bmp.width, 2);
  EXPECT_EQ(bmp.pixel(0, 0)[0], 1.0f);  // top left red
  EXPECT_EQ(bmp.pixel(0, 0)[2], 0.0f);
  EXPECT_EQ(bmp.pixel(0, 1)[2], 1.0f);  // bottom left blue
  EXPECT_EQ(bmp.pixel(1, 1)[1], 1.0f);  // bottom right green
  EXPECT_FALSE(openImageIOIsLoaded());

  writeImage(dir / "c.tif", image);
  EXPECT_TRUE(openImageIOIsLoaded());
  const Image tiff = readImage(dir / "c.tif");
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    EXPECT_NEAR(tiff.pixels[i], image.pixels[i], 0.5f / 255.0f);
}
