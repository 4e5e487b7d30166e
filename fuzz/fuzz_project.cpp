// Fuzz target: the .kerf project loader (io/project.*, and through it annotations_json, block_knots_json,
// project_log, the parameter schema and the growth-rate grid). The input is the file's bytes.
// A project Kerf accepts must also save and load again unchanged in meaning (the round trip).
#include <nlohmann/json.hpp>

#include "fuzz_common.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path dir = kerf::fuzz::freshScratch("project");
  const std::filesystem::path file = dir / "fuzz.kerf";
  kerf::fuzz::writeBytes(file, {reinterpret_cast<const char*>(data), size});
  kerf::Project project;
  try {
    project = kerf::loadProject(file);
  } catch (const kerf::InputError&) {
    return 0;
  }
  const nlohmann::json saved = kerf::projectToJson(project, dir);
  kerf::Project again;
  try {
    again = kerf::projectFromJson(saved, dir);
  } catch (const kerf::InputError& e) {
    std::fprintf(stderr, "a saved project does not load again: %s\n", e.what());
    std::abort();
  }
  kerf::fuzz::require(kerf::projectToJson(again, dir) == saved, "save -> load -> save is stable");
  (void)again.effectiveRates();
  return 0;
}
