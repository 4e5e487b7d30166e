#include "hold_out_option.hpp"

#include "fit/held_out_faces.hpp"
#include "util/error.hpp"

namespace kerf::cli {

void addHoldOutFaceOption(CLI::App* command, std::vector<std::string>& values) {
  command
      ->add_option(kHoldOutFaceOption, values,
                   "Leave face(s) out: nothing of their photos (ring images, traces, colours, texture) is "
                   "used, so render-faces shows Kerf's prediction of them. Letters A..F, repeatable "
                   "(C, AC, or --hold-out-face A --hold-out-face C); kept in the project (held_out_faces)")
      ->expected(1)
      ->allow_extra_args(false)  // one value per occurrence: `--hold-out-face C SAMPLE` keeps SAMPLE
      ->take_all();
}

FaceSet heldOutFacesFromOption(const std::vector<std::string>& values) {
  FaceSet faces;
  for (const std::string& value : values) {
    try {
      const FaceSet these = parseFaceSet(value);
      if (these.empty()) throw InputError("no face letter given (faces are A..F)");
      faces |= these;
    } catch (const InputError& e) {
      throw InputError(std::string(kHoldOutFaceOption) + " " + value + ": " + e.what());
    }
  }
  try {
    requireFaceLeftToFit(faces);
  } catch (const InputError& e) {
    throw InputError(std::string(kHoldOutFaceOption) + ": " + e.what());
  }
  return faces;
}

}  // namespace kerf::cli
