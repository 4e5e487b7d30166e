#include "output_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include "util/error.hpp"

namespace kerf::cli {
namespace fs = std::filesystem;
namespace {

// The options whose value is a file kerf-cli writes (folders such as detect's --out are compared too:
// a folder cannot be the same file as an input file).
bool isOutputOption(const CLI::Option& option) {
  const std::string name = option.get_name();
  return name == "--out" || name == "--save-log";
}

struct Named {
  std::string option, path;
};

}  // namespace

void checkOutputsAgainstInputs(const CLI::App& command) {
  std::vector<Named> outputs, inputs;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_expected_min() == 0) continue;
    for (const std::string& value : option->results())
      (isOutputOption(*option) ? outputs : inputs).push_back({option->get_name(), value});
  }
  std::error_code error;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const fs::path a = fs::weakly_canonical(outputs[i].path, error);
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (!error && a == fs::weakly_canonical(outputs[j].path, error))
        throw InputError(outputs[i].option + " and " + outputs[j].option + " name the same file " +
                         outputs[i].path + "; each output needs its own name");
    for (const Named& input : inputs) {
      if (!fs::is_regular_file(input.path, error) || !fs::exists(outputs[i].path, error)) continue;
      if (fs::equivalent(input.path, outputs[i].path, error))
        throw InputError(outputs[i].option + " " + outputs[i].path + " is also the input " + input.option +
                         "; writing it would replace the input: choose another output name");
    }
  }
}

}  // namespace kerf::cli
