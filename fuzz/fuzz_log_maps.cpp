// Fuzz target: the Gran_1 image maps (io/log_data_import.*: importGranMaps): map_params.json and the four
// BMP maps, written to a folder from the input and imported as `kerf-cli render-board FOLDER` would.
// The input: the params (raw text, or four numbers), then each map's size and pixels.
#include <fuzzer/FuzzedDataProvider.h>

#include <nlohmann/json.hpp>

#include "fuzz_common.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"
#include "util/error.hpp"

namespace {

void writeMap(FuzzedDataProvider& in, const std::filesystem::path& path, bool knotMap) {
  const int width = knotMap && in.ConsumeBool() ? 32 : in.ConsumeIntegralInRange(1, 40);
  const int height = in.ConsumeIntegralInRange(1, knotMap ? 16 : 24);
  kerf::Image map(width, height, 3);
  for (float& v : map.pixels) v = in.ConsumeIntegral<std::uint8_t>() / 255.0f;
  kerf::writeImage(path, map);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  static const std::filesystem::path dir = kerf::fuzz::freshScratch("gran-maps");
  std::string params;
  switch (in.ConsumeIntegralInRange(0, 2)) {
    case 0:
      params = in.ConsumeRandomLengthString(80);
      break;
    case 1:
      params = nlohmann::json::array({in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>(),
                                      in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>()})
                   .dump();
      break;
    default:
      params = nlohmann::json::array({in.ConsumeIntegralInRange(-5, 100), in.ConsumeIntegralInRange(-5, 400),
                                      in.ConsumeIntegralInRange(-5, 4000), in.ConsumeIntegralInRange(-2, 6)})
                   .dump();
  }
  kerf::fuzz::writeBytes(dir / "map_params.json", params);
  writeMap(in, dir / "pith_and_radius_map.bmp", false);
  for (const char* name : {"knot_height_map.bmp", "knot_orientation_map.bmp", "knot_state_map.bmp"})
    writeMap(in, dir / name, true);
  try {
    const kerf::LogModel log = kerf::importGranMaps(dir);
    kerf::fuzz::require(kerf::fuzz::finite(log.stem.radiusAt(0.5f * log.stem.height(), 0.0f)),
                        "finite stem radius");
    (void)kerf::logFromJson(kerf::logToJson(log), "round trip");
  } catch (const kerf::InputError&) {
  }
  return 0;
}
