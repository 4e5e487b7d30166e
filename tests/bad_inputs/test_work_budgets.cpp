// Budgets derived from the work, checked before the memory or time is taken (issue 21, round two):
// inputs inside Kerf's file limits that still asked for gigabytes or minutes. Each case is a real file of
// the size the attack used (a 2 MB PNG of 10950 x 10950 px, a 10 MB log of 100k knots), refused at once
// by kerf-cli with a message naming the file, its size and the budget; the image read keeps one float
// copy. Verdicts are on exit codes, messages and memory, never on time.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "bad_input_files.hpp"
#include "field/block_knots.hpp"
#include "field/log_model.hpp"
#include "io/block_knots_json.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"
#include "refused_run.hpp"
#include "rings/detect_block_rings.hpp"
#include "util/size_limits.hpp"

using namespace kerf;
using namespace kerf::bad;

namespace {

// A real PNG of width x height pixels, `channels` 8-bit channels (1 grey, 4 RGBA), every pixel
// pixel(x, y, c), deflated row by row at zlib's fastest level.
void writePng(const fs::path& path, int width, int height, int channels,
              const std::function<unsigned char(int, int, int)>& pixel) {
  const char colourType = channels == 1 ? 0 : channels == 3 ? 2 : 6;
  const std::string ihdr =
      bigEndian(width) + bigEndian(height) + std::string{8, colourType} + std::string(3, '\0');
  z_stream z{};
  ASSERT_EQ(deflateInit(&z, 1), Z_OK);
  std::string idat, row(1 + static_cast<std::size_t>(width) * channels, '\0');
  std::vector<unsigned char> out(1 << 20);
  const auto pump = [&](int flush) {
    do {
      z.next_out = out.data();
      z.avail_out = static_cast<uInt>(out.size());
      deflate(&z, flush);
      idat.append(reinterpret_cast<const char*>(out.data()), out.size() - z.avail_out);
    } while (z.avail_out == 0);
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) row[1 + static_cast<std::size_t>(x) * channels + c] = pixel(x, y, c);
    z.next_in = reinterpret_cast<Bytef*>(row.data());
    z.avail_in = static_cast<uInt>(row.size());
    pump(Z_NO_FLUSH);
  }
  pump(Z_FINISH);
  deflateEnd(&z);
  writeText(path, std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", idat) +
                      pngChunk("IEND", ""));
}

class WorkBudgets : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("work_budgets", "out"); }
  void expectRefused(const std::string& arguments, const std::string& problem) {
    expectRefusedAtOnce(runCli(arguments), problem, dir_ / "out");
  }
  fs::path dir_;
};

// The example: six grey 10950 x 10950 faces (2 MB each as PNG, 120 megapixels: inside the image
// limit) kept detect busy for minutes. Refused from the headers, before a photo is decoded.
TEST_F(WorkBudgets, SixHugeGreyFacesAreRefusedByDetectBeforeDecoding) {
  const fs::path sample = dir_ / "sample";
  fs::create_directories(sample);
  writePng(sample / "A_col.png", 10950, 10950, 1,
           [](int x, int y, int) { return (x / 64 + y / 64) % 2 * 40 + 100; });
  EXPECT_GT(fs::file_size(sample / "A_col.png"), 1'000'000u);
  for (const char* face : {"B", "C", "D", "E", "F"})
    fs::create_hard_link(sample / "A_col.png", sample / (std::string(face) + "_col.png"));
  expectRefused("detect " + sample.string() + " --out " + (dir_ / "out").string(),
                "face A photo .*A_col.png is 10950 x 10950 px \\(119.9 megapixels\\); ring detection takes "
                "faces of up to 2 megapixels");
}

TEST_F(WorkBudgets, RingDetectionBudgetIsPerFace) {
  EXPECT_NO_THROW(checkRingDetectionSize(1414, 1414, "face A"));
  const std::string message = errorOf([] { checkRingDetectionSize(1415, 1415, "the photo of face C"); });
  EXPECT_NE(message.find("the photo of face C is 1415 x 1415 px (2.002 megapixels)"), std::string::npos)
      << message;
  // The core's loop checks every face before it detects on any (the editor's Detect Rings goes there).
  std::array<Image, 6> photos;
  photos[0] = Image(16, 16, 3);
  photos[4] = Image(2000, 1001, 3);
  const std::string loop = errorOf([&] { detectBlockRings(photos, Block()); });
  EXPECT_NE(loop.find("the photo of face E is 2000 x 1001 px"), std::string::npos) << loop;
}

// Reading needs one float copy at the channels kept; the budget is 80 % of the usable memory. The
// message names the file, its pixels and the budget.
TEST_F(WorkBudgets, ImageReadMemoryBudgetNamesTheFilePixelsAndBudget) {
  EXPECT_NO_THROW(checkImageReadMemory("x.png", 10950, 10950, 3, 8ull << 30));
  const std::string message =
      errorOf([] { checkImageReadMemory("/photos/x.png", 10950, 10950, 3, 1ull << 30); });
  EXPECT_TRUE(std::regex_search(
      message, std::regex("image /photos/x.png is 10950 x 10950 px \\(119.9 megapixels\\): reading it takes "
                          "1.3 GiB of memory \\(3 float channels a pixel\\) and Kerf's budget for it is 0.8 "
                          "GiB")))
      << message;
}

// An RGBA photo is decoded a strip at a time into RGB: the read takes one RGB float copy (108 MB for 3000
// x 3000 px), where the old read took the RGBA copy and the RGB one (252 MB). Measured in a forked child,
// whose peak memory (ru_maxrss) starts at what this process holds.
TEST_F(WorkBudgets, RgbaPhotoIsReadWithOneFloatCopy) {
  constexpr int kSide = 3000;
  const fs::path file = dir_ / "rgba.png";
  writePng(file, kSide, kSide, 4, [](int x, int y, int c) {
    return static_cast<unsigned char>(c == 0 ? x % 251 : c == 1 ? y % 241 : c == 2 ? 7 : 0);
  });
  int pipeFds[2];
  ASSERT_EQ(::pipe(pipeFds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    long before = 0, resident = 0;
    if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(statm, "%ld %ld", &before, &resident) != 2) resident = 0;
      std::fclose(statm);
    }
    long values[3] = {resident * (::sysconf(_SC_PAGESIZE) / 1024), 0, 0};
    try {
      const Image image = readImage(file);
      const float* p = image.pixel(1000, 2000);
      values[2] = image.channels == 3 && std::abs(p[0] - 1000 % 251 / 255.0f) < 1e-6f &&
                  std::abs(p[1] - 2000 % 241 / 255.0f) < 1e-6f && std::abs(p[2] - 7 / 255.0f) < 1e-6f;
    } catch (...) {
    }
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    values[1] = usage.ru_maxrss;
    if (::write(pipeFds[1], values, sizeof values) != sizeof values) ::_exit(2);
    ::_exit(0);
  }
  ::close(pipeFds[1]);
  long values[3] = {};
  const ssize_t got = ::read(pipeFds[0], values, sizeof values);
  ::close(pipeFds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_EQ(got, static_cast<ssize_t>(sizeof values));
  EXPECT_EQ(values[2], 1) << "the RGBA photo did not read back as its RGB values";
  const double rgbCopyKiB = double(kSide) * kSide * 3 * sizeof(float) / 1024.0;
  const double grewKiB = double(values[1] - values[0]);
  std::printf("reading the %d x %d RGBA PNG grew the peak by %.0f MiB (one RGB float copy: %.0f MiB)\n",
              kSide, kSide, grewKiB / 1024, rgbCopyKiB / 1024);
#if defined(__SANITIZE_ADDRESS__)
  // ASan keeps freed blocks in quarantine (256 MB by default), so the decoder's freed row buffers stay
  // resident: the peak says nothing about the read here. The Release build checks it.
  GTEST_SKIP() << "the peak memory of a read is not measurable under AddressSanitizer (quarantine)";
#endif
  EXPECT_LT(grewKiB, 1.5 * rgbCopyKiB)
      << "reading took " << grewKiB / 1024 << " MiB beyond the " << values[0] / 1024
      << " MiB held before; one RGB copy is " << rgbCopyKiB / 1024 << " MiB";
}

// The example: a 10 MB log of 100k knots needed 3.4 GB (two noise tables per knot). Twice the
// budget here, with knots of two samples (1.4 MB), to keep the test fast; the 100k-knot file was refused
// the same way by hand (docs/reliability.md).
TEST_F(WorkBudgets, LogOfTwiceTheKnotBudgetIsRefusedNamingTheFile) {
  RandomLogOptions options;
  options.lengthMm = 400.0f;
  const fs::path file = dir_ / "many-knots.kerflog";
  saveLogFile(generateRandomLog(options), file);
  nlohmann::json log = nlohmann::json::parse(readBytes(file));
  const nlohmann::json knot = {
      {"distance_step_mm", 4.0}, {"height_mm", {100.0, 104.0}}, {"azimuth_rad", {0.0, 0.5}}};
  log["knots"] = nlohmann::json::array();
  for (std::size_t k = 0; k < 2 * kMaxLogKnots; ++k) log["knots"].push_back(knot);
  writeText(file, log.dump());
  expectRefused(
      "render-board " + file.string() + " --out " + (dir_ / "out" / "board.png").string() + " --res 64",
      "log file .*many-knots.kerflog holds 20000 knots; Kerf takes at most 10000 knots in a log");
  // A log made otherwise is held to the same budget when its knot field is built.
  LogModel big = generateRandomLog(options);
  ASSERT_FALSE(big.knots.empty());
  big.knots.resize(kMaxLogKnots + 1, big.knots.front());
  EXPECT_NE(errorOf([&] { validate(big); }).find("holds 10001 knots"), std::string::npos);
}

TEST_F(WorkBudgets, LogMapsKnotCountOverTheBudgetIsRefused) {
  const fs::path folder = dir_ / "gran-maps";
  fs::create_directories(folder);
  writeText(folder / "map_params.json", "[10, 100, 1000, 10001]");
  const std::string message = errorOf([&] { loadLog(folder); });
  EXPECT_NE(message.find("knot count must be a whole number from 0 to 10000"), std::string::npos) << message;
}

// A block's knots are each evaluated at every pixel: a project of five times the budget (the attack's file
// had 100k) is refused from its list, before a knot is built.
TEST_F(WorkBudgets, ProjectOfTooManyKnotsIsRefusedNamingTheFile) {
  const fs::path file = dir_ / "many-knots.kerf";
  Project project;
  project.knots = {BlockKnot{}};
  saveProject(project, file);
  nlohmann::json json = nlohmann::json::parse(readBytes(file));
  const nlohmann::json knot = json["knots"][0];
  for (std::size_t k = 1; k < 5 * kMaxBlockKnots; ++k) json["knots"].push_back(knot);
  writeText(file, json.dump());
  expectRefused(
      "render-faces " + file.string() + " --out " + (dir_ / "out").string() + " --px-per-mm 0.5",
      "project .*many-knots.kerf: knots holds 5000 knots; Kerf takes at most 1000 knots in a block");
  std::vector<BlockKnot> knots(kMaxBlockKnots + 1);
  EXPECT_NE(errorOf([&] { BlockKnots(knots, KnotSettings{}, 2.0f); }).find("1001 knots"), std::string::npos);
}

}  // namespace
