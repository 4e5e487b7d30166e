// Safe reading of user files (issue 21): the one JSON reader (io/json_file.hpp: a depth limit, duplicate
// keys refused, short messages) and the one safe open (io/input_file.hpp: regular files only, size-capped;
// images with NaN or infinite pixels refused). Each case: the core names the file and the problem, and
// kerf-cli exits with code 2 without writing anything.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "bad_input_files.hpp"
#include "io/image.hpp"
#include "io/json_file.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"
#include "mesh/mesh_loader.hpp"
#include "run_cli.hpp"

namespace kerf::bad {
namespace {

// The length of `text` without the test folder's name in it: messages name the file, and where the build
// lives (a CI checkout's path is longer) must not decide a bound on how much of the input they echo.
std::size_t lengthBesidePaths(const std::string& text, const fs::path& folder) {
  const std::string name = folder.string();
  std::size_t length = text.size();
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + name.size()))
    length -= name.size();
  return length;
}

class SafeInputs : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("safe_inputs"); }
  // kerf-cli exits with code 2, its message matches `problem`, and `out` was not written.
  void expectCliRefuses(const std::string& arguments, const std::string& problem, const fs::path& out) {
    const CliResult r = runCli(arguments);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(problem))) << r.output;
    EXPECT_LT(lengthBesidePaths(r.output, dir_), 500u) << "the message echoes too much of the input";
    EXPECT_FALSE(fs::exists(out)) << out;
  }
  fs::path dir_;
};

std::string nested(int depth, const std::string& inner) {
  return std::string(depth, '[') + inner + std::string(depth, ']');
}

bool printable(const std::string& text) {
  for (const char c : text)
    if (c != '\n' && !std::isprint(static_cast<unsigned char>(c))) return false;
  return true;
}

TEST_F(SafeInputs, ProjectBlockSizeNested100000Deep) {
  const fs::path project = dir_ / "deep.kerf";
  writeText(project,
            R"({"format": "kerf-project", "version": 1, "block": {"size_mm": )" + nested(100000, "1") + "}}");
  const std::string error = errorOf([&] { loadDocument(project); });
  EXPECT_NE(error.find(project.string()), std::string::npos) << error;
  EXPECT_NE(error.find("nested deeper than 64 levels"), std::string::npos) << error;
  EXPECT_LT(lengthBesidePaths(error, dir_), 200u) << error;
  expectCliRefuses("render-faces " + project.string() + " --out " + (dir_ / "out").string(),
                   "deep.kerf is not valid for Kerf: lists and objects nested deeper than 64", dir_ / "out");
}

TEST_F(SafeInputs, ProjectKnotsNested100000Deep) {
  const fs::path project = dir_ / "knots.kerf";
  writeText(project, R"({"format": "kerf-project", "version": 1, "knots": )" + nested(100000, "") + "}");
  EXPECT_NE(errorOf([&] { loadProject(project); }).find("nested deeper than 64"), std::string::npos);
}

TEST_F(SafeInputs, LogNested100000Deep) {
  const fs::path log = dir_ / "deep.kerflog";
  writeText(log, R"({"format": "kerf-log", "version": 1, "stem": )" + nested(100000, "0") + "}");
  const std::string error = errorOf([&] { loadLog(log); });
  EXPECT_NE(error.find("log file " + log.string()), std::string::npos) << error;
  EXPECT_NE(error.find("nested deeper than 64"), std::string::npos) << error;
}

TEST_F(SafeInputs, DuplicateKeysAreRefusedNamingTheKey) {
  const fs::path project = dir_ / "twice.kerf";
  writeText(project, R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": 2,
                         "growth.ring_width": 3}})");
  const std::string error = errorOf([&] { loadProject(project); });
  EXPECT_NE(error.find(project.string()), std::string::npos) << error;
  EXPECT_NE(error.find("the key \"growth.ring_width\" appears twice in one object"), std::string::npos)
      << error;
  // The same key in two different objects is fine.
  EXPECT_NO_THROW(parseJsonText(R"({"a": {"x": 1}, "b": {"x": 2}})", "test"));
}

TEST_F(SafeInputs, A4MegabyteStringIsNotEchoed) {
  const fs::path project = dir_ / "long.kerf";
  writeText(project, R"({"format": ")" + std::string(4 << 20, 'a') + R"("})");
  const std::string error = errorOf([&] { loadProject(project); });
  EXPECT_NE(error.find("not a Kerf project"), std::string::npos) << error;
  EXPECT_LT(lengthBesidePaths(error, dir_), 200u) << error.substr(0, 400);
  // A string that breaks the syntax: nlohmann's message quotes the token it read; cut as well.
  writeText(project, R"({"format": ")" + std::string(4 << 20, 'a') + "\x01\"}");
  const std::string broken = errorOf([&] { loadProject(project); });
  EXPECT_NE(broken.find("is not valid JSON"), std::string::npos) << broken;
  EXPECT_LT(lengthBesidePaths(broken, dir_), 400u) << broken.substr(0, 400);
  const CliResult r = runCli("render-faces " + project.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_LT(lengthBesidePaths(r.output, dir_), 500u) << r.output.substr(0, 600);
}

TEST_F(SafeInputs, PhotoGivenAsAProjectPrintsNoBinary) {
  const fs::path photo = dir_ / "photo.png";
  writePhoto(photo, 16, 16);
  const std::string error = errorOf([&] { loadProject(photo); });
  EXPECT_NE(error.find("photo.png is not valid JSON"), std::string::npos) << error;
  EXPECT_TRUE(printable(error)) << error;
  const CliResult r = runCli("render-faces " + photo.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(printable(r.output)) << r.output;
}

TEST_F(SafeInputs, FifoAsProjectOrPhotoIsRefusedWithoutBlocking) {
  const fs::path fifo = dir_ / "pipe.kerf";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Nobody writes to the pipe: a reader that opened it would wait for ever (ctest's timeout would fail it).
  const std::string error = errorOf([&] { loadDocument(fifo); });
  EXPECT_NE(error.find("pipe.kerf: it is a pipe (FIFO), not a regular file"), std::string::npos) << error;
  EXPECT_NE(errorOf([&] { readImage(fifo); }).find("a pipe (FIFO)"), std::string::npos);
  expectCliRefuses("render-faces " + fifo.string() + " --out " + (dir_ / "out").string(), "a pipe \\(FIFO\\)",
                   dir_ / "out");
  expectCliRefuses("rectify " + fifo.string() + " --corners 0,0,9,0,9,9,0,9 --size-mm 10,10 --out " +
                       (dir_ / "face.png").string(),
                   "pipe.kerf: it is a pipe \\(FIFO\\)", dir_ / "face.png");
}

TEST_F(SafeInputs, DevZeroAsProjectPhotoOrMeshIsRefused) {
  const fs::path zero = "/dev/zero";
  EXPECT_NE(errorOf([&] { loadProject(zero); }).find("/dev/zero: it is a character device"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readImage(zero); }).find("a character device"), std::string::npos);
  expectCliRefuses(
      "rectify /dev/zero --corners 0,0,9,0,9,9,0,9 --size-mm 10,10 --out " + (dir_ / "face.png").string(),
      "/dev/zero: it is a character device", dir_ / "face.png");
  const fs::path mesh = dir_ / "zero.obj";
  fs::create_symlink(zero, mesh);  // the extension a mesh needs, the bytes of /dev/zero
  EXPECT_NE(errorOf([&] { loadMesh(mesh); }).find("a character device"), std::string::npos);
}

// A float photo with NaN / infinite pixels (32-bit TIFF, EXR): detect crashed on it.
void writeFloatPhoto(const fs::path& path, int w, int h, const std::vector<std::pair<int, float>>& bad) {
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * 3, 0.5f);
  for (const auto& [index, value] : bad) pixels[index] = value;
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  ASSERT_TRUE(out->close());
}

TEST_F(SafeInputs, FloatPhotosWithNonFinitePixelsAreRefusedCountingThem) {
  const fs::path tiff = dir_ / "A_col.tif";
  writeFloatPhoto(tiff, 16, 16, {{5, std::nanf("")}});
  const std::string error = errorOf([&] { readImage(tiff); });
  EXPECT_NE(error.find("A_col.tif has 1 pixel that is not a finite number"), std::string::npos) << error;
  const fs::path exr = dir_ / "photo.exr";
  writeFloatPhoto(exr, 16, 16, {{0, INFINITY}, {1, -INFINITY}, {30, std::nanf("")}});
  EXPECT_NE(errorOf([&] { readImage(exr); }).find("photo.exr has 2 pixels"), std::string::npos);
  expectCliRefuses("rectify " + exr.string() + " --corners 0,0,15,0,15,15,0,15 --size-mm 10,10 --out " +
                       (dir_ / "face.png").string(),
                   "photo.exr has 2 pixels that are not finite", dir_ / "face.png");
  // In a sample folder, through detect.
  const fs::path sample = dir_ / "sample";
  fs::create_directories(sample);
  writeSample(sample);
  fs::remove(sample / "A_col.png");
  writeFloatPhoto(sample / "A_col.tif", 16, 16, {{7, std::nanf("")}});
  expectCliRefuses("detect " + sample.string() + " --out " + (dir_ / "rings").string(),
                   "A_col.tif has 1 pixel that is not a finite", dir_ / "rings");
}

}  // namespace
}  // namespace kerf::bad
