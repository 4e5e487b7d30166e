// Fuzz target: opening a Mokume-style sample folder (io/project.cpp projectFromSampleFolder,
// io/sample_folder.*, and the annotation readers of rings/annotations.*), as `kerf-cli fit FOLDER` or the
// editor's File > Open does. The input chooses block.json's text, which face photos exist and their
// sizes, and the numbered-ring and knot images with their pixels.
#include <fuzzer/FuzzedDataProvider.h>

#include <nlohmann/json.hpp>

#include "fuzz_common.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

namespace {

void writeGrey(FuzzedDataProvider& in, const std::filesystem::path& path, bool pixels) {
  kerf::Image image(in.ConsumeIntegralInRange(1, 48), in.ConsumeIntegralInRange(1, 48), 1);
  if (pixels)
    for (float& v : image.pixels) v = in.ConsumeIntegral<std::uint8_t>() / 255.0f;
  kerf::writeImage(path, image);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const std::filesystem::path dir = kerf::fuzz::freshScratch("sample");
  switch (in.ConsumeIntegralInRange(0, 2)) {
    case 0:
      break;  // no block.json: a 40 mm cube
    case 1:
      kerf::fuzz::writeBytes(dir / "block.json", in.ConsumeRandomLengthString(60));
      break;
    default:
      kerf::fuzz::writeBytes(dir / "block.json", nlohmann::json{{"size_mm",
                                                                 {in.ConsumeIntegralInRange(-1, 80),
                                                                  in.ConsumeIntegralInRange(-1, 80),
                                                                  in.ConsumeIntegralInRange(-1, 80)}}}
                                                     .dump());
  }
  for (const char letter : {'A', 'B', 'C', 'D', 'E', 'F'}) {
    const std::string face(1, letter);
    if (in.ConsumeBool()) writeGrey(in, dir / (face + "_col.png"), false);
    if (in.ConsumeBool()) writeGrey(in, dir / (face + "_ann.png"), true);
    if (in.ConsumeBool()) writeGrey(in, dir / (face + "_knot.png"), true);
  }
  try {
    const kerf::Project project = kerf::projectFromSampleFolder(dir);
    for (const kerf::RingTrace& trace : project.annotations.traces)
      for (glm::vec2 p : trace.points)
        kerf::fuzz::require(kerf::fuzz::finite(p.x) && kerf::fuzz::finite(p.y), "finite trace point");
  } catch (const kerf::InputError&) {
  }
  return 0;
}
