// The validated-number layer (util/parse_number.hpp, issue 21), by table: what it accepts and what it
// refuses, in every type Kerf reads numbers into; then kerf-cli's options, `--set` and the JSON readers,
// each refusing with exit code 2 and a message naming the option or the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>

#include "bad_input_files.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"
#include "rings/annotations.hpp"
#include "run_cli.hpp"
#include "util/number_list.hpp"
#include "util/parse_number.hpp"

namespace kerf::bad {
namespace {

struct NumberCase {
  std::string text;
  std::function<double(const std::string&)> parse;  // throws InputError
  std::string expected;  // "=VALUE" when accepted, else a regex the message must match
};

double asFloat(const std::string& t) {
  return parseNumber<float>(t, "x");
}
double asDouble(const std::string& t) {
  return parseNumber<double>(t, "x");
}
double asInt(const std::string& t) {
  return parseNumber<int>(t, "x");
}
double asCount32(const std::string& t) {
  return parseNumber<std::uint32_t>(t, "x");
}
double asPercent(const std::string& t) {
  return parseNumber<double>(t, "x", 0.0, 100.0);
}

const NumberCase kNumbers[] = {
    {"0.5", asFloat, "=0.5"},
    {" 2.5 ", asFloat, "=2.5"},
    {"+3", asFloat, "=3"},
    {"-1e3", asDouble, "=-1000"},
    {"1e308", asDouble, "=1e308"},
    {"1e308", asFloat, "x: \"1e308\" is outside"},  // was read as inf, then written back as null
    {"1e999", asDouble, "is too large or too small"},
    {"nan", asFloat, "x: \"nan\" is not a finite number"},
    {"NaN", asDouble, "is not a finite number"},
    {"inf", asDouble, "is not a finite number"},
    {"-infinity", asFloat, "is not a finite number"},
    {"0.5junk", asFloat, "x: \"0.5junk\" is not a number"},
    {"", asFloat, "is not a number"},
    {"0x10", asInt, "is not a number"},  // CLI11 alone read hexadecimal
    {"010", asInt, "=10"},               // and octal: 010 was 8
    {"8", asInt, "=8"},
    {"1e3", asInt, "=1000"},
    {"8.9", asInt, "x: \"8.9\" is not a whole number"},
    {"4294967304", asCount32, "x: \"4294967304\" is outside the whole numbers \\[0, 4294967295\\]"},
    {"4294967295", asCount32, "=4294967295"},
    {"-1", asCount32, "is outside the whole numbers"},  // was wrapped to 4294967295
    {"-0", asCount32, "=0"},
    {"2147483648", asInt, "is outside the whole numbers"},
    {"101", asPercent, "x: \"101\" is outside \\[0, 100\\]"},
    {"-0.001", asPercent, "is outside"},
    {std::string(5000, '7'), asInt, "\\.\\.\\.\" \\(5000 characters\\) is outside"},  // echo cut to 80
};

TEST(ValidatedNumbers, Table) {
  for (const NumberCase& c : kNumbers) {
    SCOPED_TRACE("text \"" + c.text.substr(0, 40) + "\"");
    double value = 0;
    const std::string error = errorOf([&] { value = c.parse(c.text); });
    if (c.expected.front() == '=') {
      EXPECT_EQ(error, "");
      EXPECT_DOUBLE_EQ(value, std::stod(c.expected.substr(1)));
    } else {
      EXPECT_TRUE(std::regex_search(error, std::regex(c.expected))) << error;
      EXPECT_LT(error.size(), 200u) << "the message echoes too much";
    }
  }
}

TEST(ValidatedNumbers, DoublesFromJsonMustFitTheirTarget) {
  EXPECT_EQ(checkedNumber<int>(8.0, "n"), 8);
  EXPECT_NE(errorOf([] { checkedNumber<int>(8.9, "n"); }).find("n: \"8.9"), std::string::npos);
  EXPECT_NE(errorOf([] { checkedNumber<int>(4294967304.0, "n"); }).find("outside"), std::string::npos);
  EXPECT_NE(errorOf([] { checkedNumber<float>(1e308, "f"); }).find("outside"), std::string::npos);
  EXPECT_NE(errorOf([] { checkedNumber<float>(std::nan(""), "f"); }).find("not a finite"), std::string::npos);
  EXPECT_EQ(parseNumberList("1, 2.5,-3", "--l"), (std::vector<float>{1.0f, 2.5f, -3.0f}));
  EXPECT_NE(errorOf([] { parseNumberList("1,nan", "--l"); }).find("--l: \"nan\""), std::string::npos);
}

// kerf-cli: every numeric option goes through the layer (main.cpp refuses to start if one does not).
struct CliCase {
  std::string arguments;
  std::string expected;  // regex on the output; the exit code must be 2
};

const CliCase kCliCases[] = {
    {"fit {dir} --out {dir}/x.kerf --anatomy-weight nan", "--anatomy-weight: \"nan\" is not a finite number"},
    {"render-panel random:1 --type veneer --out {dir}/x.png --start nan", "--start: \"nan\" is not a finite"},
    {"render-panel random:1 --type veneer --out {dir}/x.png --height nan",
     "--height: \"nan\" is not a finite"},
    {"rectify {dir}/p.png --corners 0,0,1,0,1,1,0,1 --size-mm 1,1 --px-per-mm nan --out {dir}/x.png",
     "--px-per-mm: \"nan\" is not a finite"},
    {"render-board random:1 --out {dir}/x.png --across-knot 0 --distance nan", "--distance: \"nan\""},
    {"render-board random:1 --out {dir}/x.png --res 0x40", "--res: \"0x40\" is not a number"},
    {"render-panel random:1 --type clt --out {dir}/x.png --seed 4294967304",
     "--seed: \"4294967304\" is outside"},
    {"render-panel random:1 --type clt --out {dir}/x.png --seed -1", "--seed: \"-1\" is outside"},
    {"demo --out {dir}/demo --size 8.9", "--size: \"8.9\" is not a whole number"},
    {"render-panel random:1 --type clt --out {dir}/x.png --lamella-width 1e308",
     "--lamella-width: \"1e308\""},
    {"render-board random:1 --out {dir}/x.png --set knots.butterfly=0.5junk",
     "--set knots.butterfly: \"0.5junk\" is not a number"},
    {"render-board random:1 --out {dir}/x.png --set knots.butterfly=nan", "--set knots.butterfly: \"nan\""},
    {"render-board random:1 --out {dir}/x.png --set knots.butterfly=0.5,0.5", "needs 1 number\\(s\\), got 2"},
    {"render-board random:4294967304 --out {dir}/x.png", "LOG random:SEED: \"4294967304\" is outside"},
    {"render-panel random:1 --type clt --out {dir}/x.png --size 600,nan,90",
     "--size: \"nan\" is not a finite"},
    {"--threads 1.5 params", "--threads: \"1.5\" is not a whole number"},
};

class CliNumbers : public ::testing::TestWithParam<CliCase> {};

// One kerf-cli run per case (each its own ctest test: a run costs kerf-cli's start-up).
TEST_P(CliNumbers, RefusedWithExitCode2NamingTheOption) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(test->test_suite_name()) + "_" + test->name();
  std::replace(name.begin(), name.end(), '/', '_');
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "validated_numbers" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  writePhoto(dir / "p.png", 8, 8);
  saveProject(Project(), dir / "b.kerf");
  std::string arguments = GetParam().arguments;
  for (std::size_t at; (at = arguments.find("{dir}")) != std::string::npos;)
    arguments.replace(at, 5, dir.string());
  SCOPED_TRACE(arguments);
  const CliResult r = runCli(arguments);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(GetParam().expected))) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png") || fs::exists(dir / "x.kerf") || fs::exists(dir / "demo") ||
               fs::exists(dir / "x"));
}

INSTANTIATE_TEST_SUITE_P(ValidatedNumbers, CliNumbers, ::testing::ValuesIn(kCliCases));

// Counts and sizes computed from options, checked in double before anything is allocated (an int
// overflowed before the size check, or the work exhausted memory).
const CliCase kBudgetCases[] = {
    {"render-panel random:1 --type clt --res 16 --out {dir}/x.png --lamella-width 1e-30",
     "CLT: 1e-30 mm lamellas .* would make 6e\\+32 lamellas a layer"},
    {"render-panel random:1 --type clt --res 16 --out {dir}/x.png --lamella-width 1e-6",
     "would make 6e\\+08 lamellas a layer.*up to 10000"},
    {"render-panel random:1 --type clt --res 16 --out {dir}/x.png --size 1e-30,600,90",
     "CLT: the panel size 1e-30 x 600 x 90 mm is outside 0.01 .. 100000 mm"},
    {"render-panel random:1 --type plywood --res 16 --out {dir}/x.png --size 600,1e-30,12",
     "plywood: the panel size 600 x 1e-30 x 12 mm is outside"},
    {"export {dir}/b.kerf --depth-stack A,1e-30,1 --out {dir}/x",
     "the depth stack would have more than 10000 images \\(1 mm in steps of 1e-30 mm\\)"},
};

INSTANTIATE_TEST_SUITE_P(BudgetsBeforeAllocating, CliNumbers, ::testing::ValuesIn(kBudgetCases));

// Valid numbers that describe nothing real (issue 21): each needs a rule of its own.
const CliCase kImplausibleCases[] = {
    {"render-board random:1 --out {dir}/x.png --res 16 --board 1000000,0,500,100,100,30",
     "the board \\(centre 1e\\+06, 0, 500 mm\\) lies entirely outside the log"},
    {"render-board random:1 --out {dir}/x.png --res 16 --board 0,0,-5000,100,100,30",
     "lies entirely outside the log: the stem spans heights 0 to"},
};

INSTANTIATE_TEST_SUITE_P(ImplausibleValues, CliNumbers, ::testing::ValuesIn(kImplausibleCases));

// Numbers in files: the project, log and annotation readers.
struct FileCase {
  std::string name;
  std::string json;      // a project
  std::string expected;  // regex
};

const FileCase kFileCases[] = {
    {"GrowthRateCountThatWraps",
     R"({"format": "kerf-project", "version": 1, "growth_rates": {"heights": 4294967304, "azimuths": 2, "radii": 2,
        "height_range_mm": [0, 1], "radius_range_mm": [0, 1], "rates": [1,1,1,1,1,1,1,1]}})",
     "growth_rates.heights: \"4294967304\" is outside"},
    {"GrowthRateCountNotWhole",
     R"({"format": "kerf-project", "version": 1, "growth_rates": {"heights": 8.9, "azimuths": 2, "radii": 2,
        "height_range_mm": [0, 1], "radius_range_mm": [0, 1], "rates": [1,1,1,1,1,1,1,1]}})",
     "growth_rates.heights: \"8.9[0-9]*\" is not a whole number"},
    {"TraceYearThatWraps",
     R"({"format": "kerf-project", "version": 1, "annotations": {"units": "face_mm", "traces": [
        {"face": "A", "points": [[1, 1], [2, 2]], "year": 4294967299}]}})",
     "annotations.traces\\[0\\].year: \"4294967299\" is outside"},
    {"ParameterTooLargeForAFloat",
     R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": 1e308}})",
     "parameter growth.ring_width: \"1e\\+308\" is outside"},
    {"BlockSideTooLargeForAFloat",
     R"({"format": "kerf-project", "version": 1, "block": {"size_mm": [1e308, 1, 1]}})",
     "block.size_mm: \"1e\\+308\" is outside"},
    {"KnotIdThatWraps",
     R"({"format": "kerf-project", "version": 1, "knots": [{"id": 4294967297, "origin": [0,0,0],
        "direction": [1,0,0], "speed": 1}]})",
     "knots\\[0\\].id: \"4294967297\" is outside"},
    {"BlockOf1e-30Mm", R"({"format": "kerf-project", "version": 1, "block": {"size_mm": [1e-30, 40, 40]}})",
     "block size must be three positive lengths of at least 0.01 mm and at most 100000 mm, got 1e-30 x 40 "
     "x 40"},
    {"VersionThatWraps", R"({"format": "kerf-project", "version": 4294967297})",
     "version: \"4294967297\" is outside"},
};

TEST(ValidatedNumbers, FileNumbersThatDoNotFitAreRefused) {
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "validated_numbers_files";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const FileCase& c : kFileCases) {
    SCOPED_TRACE(c.name);
    const fs::path file = dir / (c.name + ".kerf");
    writeText(file, c.json);
    const std::string error = errorOf([&] { loadProject(file); });
    EXPECT_NE(error.find(file.string()), std::string::npos) << error;
    EXPECT_TRUE(std::regex_search(error, std::regex(c.expected))) << error;
  }
  // kerf-cli reads projects with the same reader: one run shows the exit code.
  const CliResult r = runCli("render-faces " + (dir / "TraceYearThatWraps.kerf").string() + " --out " +
                             (dir / "out").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("year: \"4294967299\" is outside"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace kerf::bad

namespace kerf::bad {
namespace {

// A trace year that fits an int but not a Mokume ring image (pixel = year, 255 = background): 300 was
// written as 254.
TEST(ValidatedNumbers, TraceYearOutsideAMokumeImageIsRefusedOnExport) {
  Annotations annotations;
  RingTrace trace;
  trace.face = FaceId::A;
  trace.points = {{5.0f, 5.0f}, {20.0f, 20.0f}};
  trace.year = 300;
  annotations.traces.push_back(trace);
  const std::string error = errorOf([&] {
    ringImageFromTraces(annotations, FaceId::A, Block(glm::vec3(40.0f)), {64, 64});
  });
  EXPECT_NE(error.find("year 300 on face A does not fit a Mokume ring image (years 0 to 254)"),
            std::string::npos)
      << error;
  annotations.traces[0].year = 254;
  EXPECT_EQ(errorOf([&] {
              ringImageFromTraces(annotations, FaceId::A, Block(glm::vec3(40.0f)), {64, 64});
            }),
            "");
}

}  // namespace
}  // namespace kerf::bad
