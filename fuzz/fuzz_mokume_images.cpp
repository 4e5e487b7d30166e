// Fuzz target: Mokume annotation images, the pixel logic of Kerf's readers (rings/annotations.*):
// numbered ring images <F>_ann.png (thinned and linked into traces) and knot images <F>_knot.png (marks at
// the centroids of grey 180..220 blobs). The input is a small grey image: its size, the face, the block,
// then the pixels (decoding PNG itself is libpng's business, not fuzzed here).
#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_common.hpp"
#include "rings/annotations.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  kerf::GrayImage8 image;
  image.width = in.ConsumeIntegralInRange(1, 64);
  image.height = in.ConsumeIntegralInRange(1, 64);
  const auto face = static_cast<kerf::FaceId>(in.ConsumeIntegralInRange(0, 5));
  const glm::vec3 blockMm(in.ConsumeIntegralInRange(1, 400), in.ConsumeIntegralInRange(1, 400),
                          in.ConsumeIntegralInRange(1, 400));
  const int minPixels = in.ConsumeIntegralInRange(0, 8);
  image.pixels = in.ConsumeBytes<std::uint8_t>(static_cast<std::size_t>(image.width) * image.height);
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height, 255);
  const kerf::Block block(blockMm);
  const glm::vec2 faceMm = kerf::faceSizeMm(block, face);
  // Image points lie on the face: within half a pixel of it at worst.
  const auto onFace = [&](glm::vec2 p) {
    return kerf::fuzz::finite(p.x) && kerf::fuzz::finite(p.y) && p.x >= -1e-3f && p.y >= -1e-3f &&
           p.x <= faceMm.x * 1.001f && p.y <= faceMm.y * 1.001f;
  };
  for (const kerf::RingTrace& trace : kerf::ringTracesFromImage(image, face, block, minPixels)) {
    kerf::fuzz::require(trace.year && *trace.year >= 0 && *trace.year < 255, "ring year is a pixel value");
    for (glm::vec2 p : trace.points) kerf::fuzz::require(onFace(p), "ring trace point on the face");
  }
  for (const kerf::KnotMark& mark : kerf::knotMarksFromImage(image, face, block))
    kerf::fuzz::require(onFace(mark.point), "knot mark on the face");
  return 0;
}
