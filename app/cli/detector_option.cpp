#include "detector_option.hpp"

namespace kerf::cli {

void addDetectorOption(CLI::App* command, std::string& value) {
  command
      ->add_option("--detector", value,
                   "Ring detector for photos without a ring map: 'learned' (Kerf's network, trained on "
                   "Kerf's own rendered wood; tells the ring boundary from the other edge of the latewood "
                   "band) or 'classical' (filters; the fallback)")
      ->check(CLI::IsMember({"classical", "learned"}))
      ->capture_default_str();
}

}  // namespace kerf::cli
