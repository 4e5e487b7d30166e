// Logs in and out (core/io/log_data_import.hpp): the CT-measured spruce log Gran_1 from its JSON files and
// from its image maps (the same log up to the maps' 8-bit quantisation), Kerf's log file round trip, and
// messages for bad input.
#include <gtest/gtest.h>

#include "spruce_log.hpp"
#include "test_files.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "field/knot_field.hpp"
#include "io/log_data_import.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

using kerf::testing::granFolder;

fs::path scratch(const std::string& name) {
  return kerf::testing::scratchFolder("log-io", name);
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST(LogImport, GranJsonHasTheWholeLog) {
  SKIP_WITHOUT_GRAN();
  const LogModel log = importGranJson(granFolder());
  EXPECT_EQ(log.stem.slices(), 400);
  EXPECT_EQ(log.stem.azimuths, 360);
  EXPECT_FLOAT_EQ(log.stem.heightStep, 10.0f);
  EXPECT_EQ(log.knots.size(), 108u);
  EXPECT_EQ(log.stem.pith[200], glm::vec2(0.0f));    // the log frame's origin: the middle slice's pith
  EXPECT_NEAR(log.stem.minRadius(), 104.06f, 3.0f);  // smoothed radii lie inside the raw range
  EXPECT_NEAR(log.stem.maxRadius(), 143.375f, 6.0f);
  // Knot 3: C = 210.531, D = 0.0548437, E = -0.414699, F = 2.6758, G = -0.00111074, H = 135, I = 135.
  const Knot& k = log.knots[3];
  EXPECT_NEAR(k.heightAt(0.0f), 210.531f, 1e-3f);
  const float d = 100.0f;
  EXPECT_NEAR(k.heightAt(d), 210.531f - (0.0548437f * 10.0f - 0.414699f * d), 0.3f);  // rises ~41 mm
  EXPECT_NEAR(k.azimuthAt(0.0f), 2.6758f, 1e-5f);
  EXPECT_FLOAT_EQ(k.deathDistance, 135.0f);
  EXPECT_FLOAT_EQ(k.endDistance, 135.0f);
  // Raw radii: without smoothing the extremes are exactly the data's.
  const LogModel raw = importGranJson(granFolder(), {.smoothJsonRadii = false});
  EXPECT_FLOAT_EQ(raw.stem.minRadius(), 104.06f);
  EXPECT_FLOAT_EQ(raw.stem.maxRadius(), 143.375f);
}

// The maps are an 8-bit encoding of the JSON (PEER_SHADERS.md A.3); decoded with bin centres, they give the
// same log within half a quantisation step of each quantity (plus the resize of the radius map).
TEST(LogImport, JsonAndMapsGiveTheSameLog) {
  SKIP_WITHOUT_GRAN();
  const LogModel json = importGranJson(granFolder(), {.mapStartAzimuthSlip = true});
  const LogModel maps = importGranMaps(granFolder());
  const float rmin = 104.06f, rmax = 143.375f, hmax = 4000.0f;
  ASSERT_EQ(json.stem.slices(), maps.stem.slices());
  ASSERT_EQ(json.knots.size(), maps.knots.size());
  float pithErr = 0, radiusErr = 0;
  for (int i = 0; i < json.stem.slices(); ++i) {
    pithErr = std::max({pithErr, std::abs(json.stem.pith[i].x - maps.stem.pith[i].x),
                        std::abs(json.stem.pith[i].y - maps.stem.pith[i].y)});
    if (i < 5 || i >= json.stem.slices() - 5) continue;  // the maps' blur wrapped the log's ends together
    for (int a = 0; a < 360; a += 7) {
      const float z = json.stem.heightStep * i, az = a * kPi / 180.0f;
      radiusErr = std::max(radiusErr, std::abs(json.stem.radiusAt(z, az) - maps.stem.radiusAt(z, az)));
    }
  }
  EXPECT_LT(pithErr, 0.5f * rmin / 255.0f + 1e-3f);  // 0.2 mm
  EXPECT_LT(radiusErr, 0.6f);                        // 0.08 mm quantisation + the 360 -> 180 resize
  float startErr = 0, courseErr = 0, twistErr = 0, startAzErr = 0, deathErr = 0;
  for (std::size_t k = 0; k < json.knots.size(); ++k) {
    const Knot &a = json.knots[k], &b = maps.knots[k];
    ASSERT_EQ(a.samples(), b.samples());
    EXPECT_FLOAT_EQ(a.distanceStep, b.distanceStep);
    startErr = std::max(startErr, std::abs(a.heights[0] - b.heights[0]));
    for (int j = 0; j < a.samples(); ++j) {
      courseErr =
          std::max(courseErr, std::abs((a.heights[j] - a.heights[0]) - (b.heights[j] - b.heights[0])));
      twistErr =
          std::max(twistErr, std::abs((a.azimuths[j] - a.azimuths[0]) - (b.azimuths[j] - b.azimuths[0])));
    }
    float da = a.azimuths[0] - b.azimuths[0];
    da -= 2.0f * kPi * std::round(da / (2.0f * kPi));
    startAzErr = std::max(startAzErr, std::abs(da));
    deathErr = std::max(deathErr, std::abs(a.deathDistance - b.deathDistance));
  }
  EXPECT_LE(startErr, 0.5f * hmax / 255.0f + 1e-2f);   // 7.8 mm: the maps' start height resolution
  EXPECT_LE(courseErr, rmin / 255.0f + 1e-2f);         // 0.41 mm
  EXPECT_LE(twistErr, 0.5f * kPi / 255.0f + 1e-4f);    // 0.006 rad
  EXPECT_LE(startAzErr, 2.0f * kPi / 255.0f + 1e-4f);  // 1.4 deg (truncated, not centred)
  EXPECT_LE(deathErr, 0.5f * rmax / 255.0f + 1e-2f);   // 0.28 mm
  std::printf(
      "JSON vs maps, largest differences: pith %.3f mm, radius %.3f mm, knot start %.2f mm, course %.3f mm, "
      "twist %.4f rad, start azimuth %.4f rad, death %.3f mm\n",
      pithErr, radiusErr, startErr, courseErr, twistErr, startAzErr, deathErr);
  // Without the slip the JSON keeps the true azimuths, which the maps do not hold.
  const LogModel trueAzimuths = importGranJson(granFolder());
  int differ = 0;
  for (std::size_t k = 0; k < json.knots.size(); ++k) {
    differ += std::abs(std::remainder(trueAzimuths.knots[k].azimuths[0] - maps.knots[k].azimuths[0],
                                      2.0f * kPi)) > 0.1f;
  }
  EXPECT_GT(differ, 50);
}

TEST(LogImport, FolderLoadsWithItsColorMap) {
  SKIP_WITHOUT_GRAN();
  const LogModel log = loadLog(granFolder());
  EXPECT_EQ(log.knots.size(), 108u);
  ASSERT_EQ(log.colorMap.colors.size(), 1504u);
  // The strip runs from the pith (196, 135, 101) to the bark (PEER_SHADERS.md A.3).
  EXPECT_NEAR(log.colorMap.colors.front().x * 255.0f, 196.0f, 1.0f);
  EXPECT_NEAR(log.colorMap.colors.front().y * 255.0f, 135.0f, 1.0f);
}

TEST(LogFile, RoundTripIsExact) {
  LogModel log = generateRandomLog({.seed = 5});
  log.knots[0].deathDistance = std::numeric_limits<float>::infinity();
  log.knots[1].deathDistance = 37.25f;
  log.colorMap.colors = {{0.1f, 0.2f, 0.3f}, {0.4f, 0.5f, 0.6f}};
  const fs::path path = scratch("round-trip") / "log.kerflog";
  saveLogFile(log, path);
  const LogModel back = loadLogFile(path);
  EXPECT_EQ(back.name, log.name);
  EXPECT_EQ(back.stem.heightStep, log.stem.heightStep);
  EXPECT_EQ(back.stem.azimuths, log.stem.azimuths);
  EXPECT_EQ(back.stem.pith, log.stem.pith);
  EXPECT_EQ(back.stem.radii, log.stem.radii);
  ASSERT_EQ(back.knots.size(), log.knots.size());
  for (std::size_t k = 0; k < log.knots.size(); ++k) {
    EXPECT_EQ(back.knots[k].heights, log.knots[k].heights);
    EXPECT_EQ(back.knots[k].azimuths, log.knots[k].azimuths);
    EXPECT_EQ(back.knots[k].distanceStep, log.knots[k].distanceStep);
    EXPECT_EQ(back.knots[k].deathDistance, log.knots[k].deathDistance);
    EXPECT_EQ(back.knots[k].endDistance, log.knots[k].endDistance);
  }
  EXPECT_EQ(back.colorMap.colors, log.colorMap.colors);
  // Written atomically: nothing but the file is left in the folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator()), 1);
  // loadLog() picks the file format from a path that is not a folder.
  EXPECT_EQ(loadLog(path).knots.size(), log.knots.size());
}

TEST(LogFile, GranRoundTripRendersTheSame) {
  SKIP_WITHOUT_GRAN();
  const LogModel log = loadLog(granFolder());
  const fs::path path = scratch("gran") / "gran1.kerflog";
  saveLogFile(log, path);
  const LogModel back = loadLogFile(path);
  const KnotField a(log, KnotSettings{}), b(back, KnotSettings{});
  for (float z = 100.0f; z < 3900.0f; z += 97.0f) {
    const glm::vec3 p(30.0f * std::cos(z), 30.0f * std::sin(z), z);
    EXPECT_EQ(a.evaluate(p).time, b.evaluate(p).time) << z;
  }
}

TEST(LogFile, BadInputSaysWhatIsWrong) {
  const fs::path dir = scratch("bad");
  EXPECT_NE(messageOf([&] { loadLog(dir / "missing.kerflog"); }).find("no such file"), std::string::npos);
  writeText(dir / "malformed.kerflog", "{\"format\": \"kerf-log\", \"version\": 1, ");
  EXPECT_NE(messageOf([&] { loadLog(dir / "malformed.kerflog"); }).find("is not valid JSON"),
            std::string::npos);
  writeText(dir / "project.kerflog", "{\"format\": \"kerf-project\", \"version\": 1}");
  EXPECT_NE(messageOf([&] { loadLogFile(dir / "project.kerflog"); }).find("not a Kerf log"),
            std::string::npos);
  writeText(dir / "future.kerflog", "{\"format\": \"kerf-log\", \"version\": 99}");
  EXPECT_NE(messageOf([&] { loadLogFile(dir / "future.kerflog"); }).find("newer Kerf"), std::string::npos);
  // A knot outside the stem.
  LogModel log = generateRandomLog({.seed = 2});
  for (float& z : log.knots[2].heights) z = -250.0f;
  EXPECT_NE(messageOf([&] { validate(log); }).find("knot 2 starts at height -250"), std::string::npos);
  EXPECT_NE(messageOf([&] { saveLogFile(log, dir / "x.kerflog"); }).find("outside the stem"),
            std::string::npos);
  // A stem whose radius table has the wrong size.
  LogModel broken = generateRandomLog({.seed = 2});
  broken.stem.radii.pop_back();
  EXPECT_NE(messageOf([&] { validate(broken); }).find("radii, expected"), std::string::npos);
  // Gran_1 folders with a file missing or malformed.
  EXPECT_NE(messageOf([&] { importGranJson(dir / "nowhere"); }).find("does not exist"), std::string::npos);
  const fs::path partial = scratch("partial");
  writeText(partial / "Gran_1_pith.json", "[[0, 0, 0], [0, 0, 10]]");
  writeText(partial / "Gran_1_radii.json", "[[100, 100, 100], [100, 100, 100]]");
  EXPECT_NE(messageOf([&] {
              importGranJson(partial);
            }).find("cannot open log file " + (partial / "Gran_1_knots.json").string()),
            std::string::npos);
  writeText(partial / "Gran_1_knots.json", "[[1, 2, 3]");
  EXPECT_NE(messageOf([&] { importGranJson(partial); }).find("Gran_1_knots.json is not valid JSON"),
            std::string::npos);
  writeText(partial / "Gran_1_knots.json", "[[0, 0, 5, 0, 0, 1, 0, \"x\", 1]]");
  EXPECT_NE(messageOf([&] { importGranJson(partial); }).find("knot 0 must be a number"), std::string::npos);
  EXPECT_NE(messageOf([&] { importGranMaps(partial); }).find("map_params.json"), std::string::npos);
}

TEST(LogFile, LogWithoutKnotsIsJustTheStem) {
  const fs::path dir = scratch("no-knots");
  writeText(dir / "Gran_1_pith.json", "[[5, 5, 0], [5, 5, 10], [5, 5, 20]]");
  writeText(dir / "Gran_1_radii.json", "[[100, 100, 100, 100], [100, 100, 100, 100], [100, 100, 100, 100]]");
  writeText(dir / "Gran_1_knots.json", "[]");
  const LogModel log = loadLog(dir);
  EXPECT_TRUE(log.knots.empty());
  EXPECT_TRUE(log.colorMap.empty());
  const KnotField field(log, KnotSettings{});
  const KnotFieldSample s = field.evaluate({40.0f, 30.0f, 10.0f});
  EXPECT_FLOAT_EQ(s.time, 0.5f);  // 50 mm from the pith (at the origin after import) / 100 mm
  EXPECT_EQ(s.knotsInReach, 0);
  const fs::path path = dir / "stem.kerflog";
  saveLogFile(log, path);
  EXPECT_TRUE(loadLogFile(path).knots.empty());
}
