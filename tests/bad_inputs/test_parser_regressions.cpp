// Inputs that crashed the readers or were undefined behaviour before their fix (found while building the
// catalogue; the fuzz targets in fuzz/ check the same rule, docs/reliability.md). Each is read as the fuzz
// targets read it; the only acceptable outcome is a value or an InputError naming the file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bad_input_files.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

using namespace kerf;
using namespace kerf::bad;
namespace fs = std::filesystem;

namespace {

fs::path scratchFile(const std::string& name, const std::string& bytes) {
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "parser_regressions";
  fs::create_directories(dir);
  kerf::bad::writeText(dir / name, bytes);
  return dir / name;
}

}  // namespace

// Project files: values of the wrong type reached nlohmann's get<>() and escaped as json::type_error,
// which kerf-cli did not catch (std::terminate).
TEST(ParserRegressions, ProjectValuesOfTheWrongType) {
  for (const std::string text :
       {R"({"format": 5, "version": 1})",
        R"({"format": "kerf-project", "version": 1, "view": {"cut_plane": {"enabled": 1}}})",
        R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": 1e400}})"}) {
    const fs::path file = scratchFile("wrong_type.kerf", text);
    EXPECT_NE(errorOf([&] { loadProject(file); }).find("wrong_type.kerf"), std::string::npos) << text;
  }
}

// Log files: a count far beyond int (UBSan: float-cast-overflow), a name that is no string.
TEST(ParserRegressions, LogCountsAndNames) {
  for (const std::string text :
       {R"({"format": "kerf-log", "version": 1, "stem": {"height_step_mm": 1, "azimuths": 1e30}})",
        R"({"format": "kerf-log", "version": 1, "name": [], "stem": {}})"}) {
    EXPECT_NE(errorOf([&] { logFromJson(nlohmann::json::parse(text), "bad.kerflog"); }).find("bad.kerflog"),
              std::string::npos)
        << text;
  }
}
