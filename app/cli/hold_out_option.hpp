#pragma once
// --hold-out-face (fit): the faces whose photos no fit may use (leave-one-face-out, docs/fitting.md,
// fit/held_out_faces.hpp). Repeatable, each value one or more letters: --hold-out-face C, AC, a,c.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "geometry/face_set.hpp"

namespace kerf::cli {

inline constexpr const char* kHoldOutFaceOption = "--hold-out-face";

void addHoldOutFaceOption(CLI::App* command, std::vector<std::string>& values);

// The faces of every value together. InputError naming the option and the bad value; also when all six
// faces are held out.
FaceSet heldOutFacesFromOption(const std::vector<std::string>& values);

}  // namespace kerf::cli
