#pragma once
// kerf-cli's numeric options, all through the validated-number layer (util/parse_number.hpp): CLI11 2.1
// alone takes "nan" and "inf" for a float (and NaN passes CLI::Range), reads "010" as octal, wraps "-1"
// into an unsigned option and turns 1e308 into an infinite float. addNumber registers the option with a
// validator that parses the text exactly as the option's own type; requireCheckedNumbers (main.cpp)
// refuses to start if any numeric option was added without it, so a new option cannot forget it.
#include <CLI/CLI.hpp>
#include <limits>
#include <string>

#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf::cli {

inline constexpr const char* kCheckedNumberValidator = "kerf-number";

template <class T>
CLI::Validator checkedNumber(T min, T max) {
  CLI::Validator v(
      [min, max](std::string& text) -> std::string {
        try {
          parseNumber<T>(text, "value", min, max);
          return {};
        } catch (const InputError& e) {
          return std::string(e.what()).substr(std::string("value: ").size());
        }
      },
      "", kCheckedNumberValidator);
  if (min != std::numeric_limits<T>::lowest() || max != std::numeric_limits<T>::max())
    v.description(detail::rangeText(min, max, std::is_integral_v<T>));
  return v;
}

// add_option for a number `target` of any arithmetic type, accepted only in [min, max].
template <class T, class Bound = T>
CLI::Option* addNumber(CLI::App* app, const std::string& name, T& target, const std::string& description,
                       Bound min, Bound max) {
  static_assert(std::is_arithmetic_v<T>, "addNumber is for numbers");
  return app->add_option(name, target, description)
      ->check(checkedNumber<T>(static_cast<T>(min), static_cast<T>(max)));
}
// ... in [min, the largest T]. (Not a default argument of the above: with an int `min` for a float
// option, Bound is int and FLT_MAX converted to int is undefined behaviour; fuzz_cli_arguments found it.)
template <class T, class Bound = T>
CLI::Option* addNumber(CLI::App* app, const std::string& name, T& target, const std::string& description,
                       Bound min) {
  return addNumber<T, T>(app, name, target, description, static_cast<T>(min), std::numeric_limits<T>::max());
}
// ... any value of T.
template <class T>
CLI::Option* addNumber(CLI::App* app, const std::string& name, T& target, const std::string& description) {
  return addNumber<T, T>(app, name, target, description, std::numeric_limits<T>::lowest(),
                         std::numeric_limits<T>::max());
}

// A length, scale or resolution: finite and above zero.
template <class T>
CLI::Option* addPositive(CLI::App* app, const std::string& name, T& target, const std::string& description) {
  static_assert(std::is_floating_point_v<T>);
  CLI::Option* option = addNumber(app, name, target, description, std::numeric_limits<T>::denorm_min(),
                                  std::numeric_limits<T>::max());
  option->get_validator(kCheckedNumberValidator)->description("> 0");
  return option;
}

// Throws std::logic_error naming every numeric option of `app` (and its subcommands) added without
// addNumber. Called once at start-up: a bug in kerf-cli, not bad input.
void requireCheckedNumbers(const CLI::App& app);

}  // namespace kerf::cli
