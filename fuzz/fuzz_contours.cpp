// Fuzz target: ring contours from a ring-localization image (rings/contours.*: the threshold, OpenCV's
// findContours and the cutting at the border), and the contours as editable traces (tracesFromContours).
// Kerf has no reader of contours.json (kerf-cli detect only writes it); this is the reader of the ARL
// images the contours come from. The input: image size, face, then 8-bit pixel values.
#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_common.hpp"
#include "rings/annotations.hpp"
#include "rings/contours.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const int width = in.ConsumeIntegralInRange(1, 96), height = in.ConsumeIntegralInRange(1, 96);
  const auto face = static_cast<kerf::FaceId>(in.ConsumeIntegralInRange(0, 5));
  kerf::ContourOptions options;
  options.threshold8 = in.ConsumeIntegralInRange(0, 255);
  options.margin = in.ConsumeIntegralInRange(-1, 8);
  options.minPoints = in.ConsumeIntegralInRange(-1, 40);
  const std::vector<std::uint8_t> bytes = in.ConsumeRemainingBytes<std::uint8_t>();
  kerf::Image arl(width, height, 1);
  for (std::size_t i = 0; i < arl.pixels.size(); ++i)
    arl.pixels[i] = i < bytes.size() ? bytes[i] / 255.0f : 0.0f;

  const auto contours = kerf::extractContours(arl, face, options);
  for (const kerf::FaceContour& c : contours)
    for (glm::ivec2 p : c.pixels)
      kerf::fuzz::require(p.x >= 0 && p.y >= 0 && p.x < width && p.y < height, "contour pixel in the image");
  const kerf::Block block(glm::vec3(40.0f, 30.0f, 50.0f));
  for (const kerf::RingTrace& trace : kerf::tracesFromContours(contours, block, {width, height}))
    for (glm::vec2 p : trace.points)
      kerf::fuzz::require(kerf::fuzz::finite(p.x) && kerf::fuzz::finite(p.y), "finite trace point");
  return 0;
}
