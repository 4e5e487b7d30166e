// PNG through libpng and BMP through stb_image (io/png_codec.hpp, io/bmp_codec.hpp) give and take exactly
// the values OpenImageIO does, which read and wrote every image before: the same floats from every kind of
// PNG, the same bytes in the files Kerf writes, and a clear error for a broken file.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <png.h>

#include "test_files.hpp"

#include <cstdio>
#include <fstream>
#include <random>

#include "io/image.hpp"
#include "io/png_codec.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

// A folder per test: ctest runs the tests of this program at the same time, in processes of their own.
fs::path scratch(const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return kerf::testing::artifactFile("codecs/" + test, name);
}

// All channels as OpenImageIO decodes them (colour as stored, as io/image.cpp asked it to).
Image readWithOiio(const fs::path& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  Image out(in->spec().width, in->spec().height, in->spec().nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::FLOAT, out.pixels.data()));
  return out;
}

void expectSamePixels(const Image& actual, const Image& expected, const std::string& what) {
  ASSERT_EQ(actual.width, expected.width) << what;
  ASSERT_EQ(actual.height, expected.height) << what;
  ASSERT_EQ(actual.channels, expected.channels) << what;
  for (std::size_t i = 0; i < actual.pixels.size(); ++i)
    ASSERT_EQ(actual.pixels[i], expected.pixels[i]) << what << ", value " << i;
}

// A PNG of any colour type, bit depth and interlacing, written with libpng itself (Kerf never writes
// palettes, low bit depths or interlacing, but photos from elsewhere have them).
struct RawPng {
  int width = 5, height = 4, colourType = PNG_COLOR_TYPE_RGB, bits = 8;
  bool interlaced = false, transparency = false;
};

bool writeRawRows(png_structp png, png_infop info, const RawPng& spec, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, spec.width, spec.height, spec.bits, spec.colourType,
               spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_color palette[4] = {{10, 20, 30}, {200, 100, 0}, {0, 255, 7}, {255, 255, 255}};
  png_byte alphas[4] = {255, 128, 0, 77};
  png_color_16 transparentGrey{};
  transparentGrey.gray = 1;
  if (spec.colourType == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, 4);
  if (spec.transparency && spec.colourType == PNG_COLOR_TYPE_PALETTE)
    png_set_tRNS(png, info, alphas, 4, nullptr);
  if (spec.transparency && spec.colourType == PNG_COLOR_TYPE_GRAY)
    png_set_tRNS(png, info, nullptr, 0, &transparentGrey);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

void writeRawPng(const fs::path& path, const RawPng& spec) {
  const int channels = spec.colourType == PNG_COLOR_TYPE_RGB          ? 3
                       : spec.colourType == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                       : spec.colourType == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                      : 1;
  const std::size_t rowBytes = (static_cast<std::size_t>(spec.width) * channels * spec.bits + 7) / 8;
  std::mt19937 random(spec.colourType * 100 + spec.bits);
  std::vector<png_byte> bytes(rowBytes * spec.height);
  for (png_byte& b : bytes) b = static_cast<png_byte>(random());
  if (spec.colourType == PNG_COLOR_TYPE_PALETTE)  // indices below the palette's 4 entries
    for (png_byte& b : bytes) b &= spec.bits == 8 ? 0x03 : 0x55;
  std::vector<png_bytep> rows;
  for (int y = 0; y < spec.height; ++y) rows.push_back(bytes.data() + y * rowBytes);
  FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_TRUE(file);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, file);
  const bool written = writeRawRows(png, info, spec, rows.data());
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
  ASSERT_TRUE(written) << path;
}

Image randomImage(int width, int height, int channels, unsigned seed) {
  Image image(width, height, channels);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> value(-0.1f, 1.1f);  // out of range too: both clamp
  for (float& v : image.pixels) v = value(random);
  // Values on and next to the rounding boundaries.
  const float edges[] = {0.0f, 1.0f, 0.5f / 255.0f, 127.5f / 255.0f, 0.5f / 65535.0f, 1e-9f, 0.99999f};
  for (std::size_t i = 0; i < std::size(edges) && i < image.pixels.size(); ++i) image.pixels[i] = edges[i];
  return image;
}

// The image as OpenImageIO stores it, colour as given: Kerf's colours are straight (unassociated), as PNG
// holds them. (Without the hint OpenImageIO divides colour by alpha, which brightened the partly covered
// edge pixels of cuts when it wrote Kerf's PNGs.)
Image writtenByOiio(const Image& image, int bits, const fs::path& path) {
  auto out = OIIO::ImageOutput::create(path.string());
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  EXPECT_TRUE(out && out->open(path.string(), spec) &&
              out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) && out->close());
  return readWithOiio(path);
}

}  // namespace

TEST(PngCodec, EveryKindOfPngReadsAsOpenImageIOReadsIt) {
  const std::vector<std::pair<std::string, RawPng>> kinds = {
      {"grey1", {.colourType = PNG_COLOR_TYPE_GRAY, .bits = 1}},
      {"grey4", {.colourType = PNG_COLOR_TYPE_GRAY, .bits = 4}},
      {"grey8", {.colourType = PNG_COLOR_TYPE_GRAY, .bits = 8}},
      {"grey16", {.colourType = PNG_COLOR_TYPE_GRAY, .bits = 16}},
      {"grey_alpha8", {.colourType = PNG_COLOR_TYPE_GRAY_ALPHA, .bits = 8}},
      {"grey_alpha16", {.colourType = PNG_COLOR_TYPE_GRAY_ALPHA, .bits = 16}},
      {"rgb8", {.colourType = PNG_COLOR_TYPE_RGB, .bits = 8}},
      {"rgb16", {.colourType = PNG_COLOR_TYPE_RGB, .bits = 16}},
      {"rgba8", {.colourType = PNG_COLOR_TYPE_RGB_ALPHA, .bits = 8}},
      {"rgba16", {.colourType = PNG_COLOR_TYPE_RGB_ALPHA, .bits = 16}},
      {"palette2", {.colourType = PNG_COLOR_TYPE_PALETTE, .bits = 2}},
      {"palette8", {.colourType = PNG_COLOR_TYPE_PALETTE, .bits = 8}},
      {"palette_transparent", {.colourType = PNG_COLOR_TYPE_PALETTE, .bits = 8, .transparency = true}},
      {"rgb8_interlaced", {.colourType = PNG_COLOR_TYPE_RGB, .bits = 8, .interlaced = true}},
      {"rgba16_interlaced", {.colourType = PNG_COLOR_TYPE_RGB_ALPHA, .bits = 16, .interlaced = true}},
  };
  for (const auto& [name, spec] : kinds) {
    const fs::path path = scratch(name + ".png");
    writeRawPng(path, spec);
    const Image oiio = readWithOiio(path);
    expectSamePixels(readImage(path, true), oiio, name + ", all channels");
    // Kerf's usual read: RGB, grey replicated, alpha dropped.
    Image rgb(oiio.width, oiio.height, 3);
    for (std::size_t p = 0; p < static_cast<std::size_t>(oiio.width) * oiio.height; ++p)
      for (int c = 0; c < 3; ++c)
        rgb.pixels[p * 3 + c] = oiio.pixels[p * oiio.channels + (oiio.channels >= 3 ? c : 0)];
    expectSamePixels(readImage(path), rgb, name + ", as RGB");
    EXPECT_EQ(readImageSize(path), glm::ivec2(spec.width, spec.height)) << name;
  }
}

TEST(PngCodec, WrittenFilesHoldOpenImageIOsQuantisation) {
  for (const int bits : {8, 16})
    for (int channels = 1; channels <= 4; ++channels) {
      const std::string name = std::to_string(channels) + "ch_" + std::to_string(bits);
      const Image image = randomImage(7, 3, channels, 10 * bits + channels);
      const fs::path kerfFile = scratch("kerf_" + name + ".png");
      writeImage(kerfFile, image, bits);
      expectSamePixels(readWithOiio(kerfFile), writtenByOiio(image, bits, scratch("oiio_" + name + ".png")),
                       name);
    }
}

TEST(PngCodec, BytesInMemoryDecodeAsTheFileDoes) {
  const Image image = randomImage(9, 4, 4, 3);
  std::vector<unsigned char> bytes = encodePngBytes(image);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(png_sig_cmp(bytes.data(), 0, 8), 0);
  const fs::path path = scratch("from_memory.png");
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const Image decoded = readWithOiio(path);
  expectSamePixels(decoded, writtenByOiio(image, 8, scratch("oiio_memory.png")), "encodePngBytes");
}

TEST(PngCodec, BrokenPngsAreRefusedNamingTheFile) {
  const fs::path good = scratch("good.png");
  writeImage(good, randomImage(40, 30, 3, 5));
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto writeBytes = [](const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
  };
  // Compressed data scrambled (the CRC no longer matches), the header's width zeroed, the tail cut.
  std::string scrambled = bytes;
  const std::size_t data = scrambled.find("IDAT") + 4;
  for (std::size_t i = data; i < data + 20; ++i) scrambled[i] = static_cast<char>(scrambled[i] ^ 0x5a);
  std::string zeroWidth = bytes;
  for (std::size_t i = 16; i < 20; ++i) zeroWidth[i] = 0;
  const std::vector<std::pair<std::string, std::string>> broken = {
      {"scrambled.png", scrambled},
      {"zero_width.png", zeroWidth},
      {"cut.png", bytes.substr(0, bytes.size() / 2)}};
  for (const auto& [name, content] : broken) {
    const fs::path path = scratch(name);
    writeBytes(path, content);
    try {
      readImage(path);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
}

TEST(BmpCodec, BmpReadsAsOpenImageIOReadsIt) {
  const Image image = randomImage(13, 6, 3, 21);
  const fs::path path = scratch("rgb.bmp");
  const Image oiio = writtenByOiio(image, 8, path);
  ASSERT_EQ(oiio.channels, 3);
  expectSamePixels(readImage(path, true), oiio, "BMP");
}

namespace {

// A 4 x 2 photo stored with EXIF Orientation `orientation`: grey where (column, row) is coded in red and
// green, 8 bits, so that every pixel can be told where it came from.
void writeOrientedTiff(const fs::path& path, int orientation, int channels) {
  OIIO::ImageSpec spec(4, 2, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("Orientation", orientation);
  std::vector<unsigned char> pixels;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      pixels.push_back(static_cast<unsigned char>(40 * x + 20));
      if (channels >= 3) {
        pixels.push_back(static_cast<unsigned char>(100 * y + 50));
        pixels.push_back(7);
      }
      if (channels == 4) pixels.push_back(255);
    }
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  ASSERT_TRUE(out->close());
}

}  // namespace

// Phones store an upright photo sideways and say so in EXIF Orientation; a cube's faces are square, so a
// face photo read as stored would be accepted turned by a quarter and every ring would lie across.
TEST(ImageOrientation, PhotosAreReadAsTheyAreShownNotAsStored) {
  // Stored (x, y) of the pixel shown at (u, v) of the upright image, for a 4 x 2 stored image (EXIF
  // 2.3 Sec. 4.6.4 Orientation: 2 mirrored, 3 turned half round, 6 row 0 on the right, 8 row 0 on the
  // left).
  struct Case {
    int orientation, width, height;
    int (*x)(int u, int v), (*y)(int u, int v);
  };
  const Case cases[] = {
      {1, 4, 2, [](int u, int) { return u; }, [](int, int v) { return v; }},
      {2, 4, 2, [](int u, int) { return 3 - u; }, [](int, int v) { return v; }},
      {3, 4, 2, [](int u, int) { return 3 - u; }, [](int, int v) { return 1 - v; }},
      {6, 2, 4, [](int, int v) { return v; }, [](int u, int) { return 1 - u; }},
      {8, 2, 4, [](int, int v) { return 3 - v; }, [](int u, int) { return u; }},
  };
  for (const int channels : {3, 4, 1})
    for (const Case& c : cases) {
      SCOPED_TRACE("orientation " + std::to_string(c.orientation) + ", " + std::to_string(channels) +
                   " channels");
      const fs::path file =
          scratch("o" + std::to_string(c.orientation) + "_" + std::to_string(channels) + ".tif");
      writeOrientedTiff(file, c.orientation, channels);
      EXPECT_EQ(readImageSize(file), glm::ivec2(c.width, c.height));
      const Image image = readImage(file);
      ASSERT_EQ(image.width, c.width);
      ASSERT_EQ(image.height, c.height);
      ASSERT_EQ(image.channels, 3);
      for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
          const float* p = image.pixel(u, v);
          EXPECT_NEAR(p[0] * 255.0f, 40 * c.x(u, v) + 20, 0.01f) << "at " << u << ", " << v;
          if (channels >= 3)
            EXPECT_NEAR(p[1] * 255.0f, 100 * c.y(u, v) + 50, 0.01f) << "at " << u << ", " << v;
          else
            EXPECT_EQ(p[1], p[0]);  // grey replicated
        }
      if (channels == 4) {
        EXPECT_EQ(readImage(file, true).channels, 4);
      }
    }
}

// A JPEG from a phone held upright (Orientation 6): read upright.
TEST(ImageOrientation, AnUprightPhoneJpegIsReadUpright) {
  const fs::path file = scratch("phone.jpg");
  OIIO::ImageSpec spec(64, 32, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("Orientation", 6);
  std::vector<unsigned char> pixels(64 * 32 * 3, 30);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 8; ++x) pixels[(y * 64 + x) * 3 + 0] = 230;  // stored: a red band on the left
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out && out->open(file.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  ASSERT_TRUE(out->close());
  const Image image = readImage(file);
  ASSERT_EQ(image.width, 32);
  ASSERT_EQ(image.height, 64);
  EXPECT_GT(image.pixel(16, 2)[0], 0.8f);   // shown: the band along the top
  EXPECT_LT(image.pixel(16, 40)[0], 0.2f);  // and nowhere else
}
