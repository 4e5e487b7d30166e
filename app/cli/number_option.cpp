#include "number_option.hpp"

#include <regex>
#include <stdexcept>

namespace kerf::cli {
namespace {

void collectUnchecked(const CLI::App& app, std::string& unchecked) {
  static const std::regex numeric(R"(\b(FLOAT|INT|UINT)\b)");
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_expected_min() == 0) continue;  // a flag
    if (!std::regex_search(option->get_type_name(), numeric)) continue;
    try {
      (void)const_cast<CLI::Option*>(option)->get_validator(kCheckedNumberValidator);
    } catch (const CLI::OptionNotFound&) {
      unchecked += " " + app.get_name() + " " + option->get_name();
    }
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    collectUnchecked(*sub, unchecked);
}

}  // namespace

void requireCheckedNumbers(const CLI::App& app) {
  std::string unchecked;
  collectUnchecked(app, unchecked);
  if (!unchecked.empty())
    throw std::logic_error("numeric options without the number check (use cli::addNumber):" + unchecked);
}

}  // namespace kerf::cli
