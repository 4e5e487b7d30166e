// Fuzz target: the JSON log readers (io/log_data_import.*). The input is one JSON document:
//  - a Kerf log file ({"format": "kerf-log", ...}), read as loadLogFile reads it; or
//  - an array [pith, radii, knots]: the three Gran_1 JSON files, written to a folder and imported.
// A log that is accepted is queried (radius, pith, knot course) and must survive a save/load round trip.
#include <nlohmann/json.hpp>

#include "fuzz_common.hpp"
#include "io/log_data_import.hpp"
#include "util/error.hpp"

namespace {

void use(const kerf::LogModel& log) {
  const float h = log.stem.height();
  for (float z : {0.0f, 0.5f * h, h}) {
    kerf::fuzz::require(kerf::fuzz::finite(log.stem.radiusAt(z, 1.0f)), "finite stem radius");
    const glm::vec2 p = log.stem.pithAt(z);
    kerf::fuzz::require(kerf::fuzz::finite(p.x) && kerf::fuzz::finite(p.y), "finite pith");
  }
  for (const kerf::Knot& knot : log.knots) {
    (void)knot.heightAt(0.5f * knot.maxDistance());
    (void)knot.azimuthAt(0.5f * knot.maxDistance());
  }
  try {
    (void)kerf::logFromJson(kerf::logToJson(log), "round trip");
  } catch (const kerf::InputError& e) {
    std::fprintf(stderr, "an accepted log does not load again: %s\n", e.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const nlohmann::json in = nlohmann::json::parse(data, data + size, nullptr, false);
  if (in.is_discarded()) return 0;  // not JSON: the readers' parse error, nothing of Kerf's to test
  try {
    if (in.is_array() && in.size() == 3) {
      static const std::filesystem::path dir = kerf::fuzz::freshScratch("gran-json");
      kerf::fuzz::writeBytes(dir / "Gran_1_pith.json", in[0].dump());
      kerf::fuzz::writeBytes(dir / "Gran_1_radii.json", in[1].dump());
      kerf::fuzz::writeBytes(dir / "Gran_1_knots.json", in[2].dump());
      use(kerf::importGranJson(dir));
    } else {
      use(kerf::logFromJson(in, "fuzz.kerflog"));
    }
  } catch (const kerf::InputError&) {
  }
  return 0;
}
