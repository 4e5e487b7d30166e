#pragma once
// --detector (detect, fit, reconstruct): which ring detector reads the photos that have no ring map
// (rings/learned_ring_detector.hpp ringDetectorNamed).
#include <CLI/CLI.hpp>
#include <string>

namespace kerf::cli {

void addDetectorOption(CLI::App* command, std::string& value);

}  // namespace kerf::cli
