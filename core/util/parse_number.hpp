#pragma once
// One validated-number layer (issue 21): every number Kerf reads from a command line, a `--set id=value`
// or a JSON file goes through here. A number is accepted only when it is finite, written without trailing
// text ("0.5junk" is refused), inside the range the caller gives, and fits the target type exactly: a
// count is a whole number (8.9 is refused, not truncated to 8) that the integer type holds (2^32 + 8 is
// refused for a 32-bit count, not wrapped to 8), and a float's value is within float's range (1e308 is
// refused, not turned into infinity). Errors are InputError naming `what` and quoting at most ~80
// characters of the offending text.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace kerf {

// `text` for an error message: quoted, cut to about `maxChars` characters with "... (N characters)".
std::string quoteForMessage(std::string_view text, std::size_t maxChars = 80);

namespace detail {
// The number `text` holds, or the reason it holds none ("is not a number", "is not finite", ...).
struct ParsedNumber {
  double value = 0.0;
  bool integerText = false;  // digits only (with a sign): parse it again as an integer for exactness
  std::string problem;       // empty when value is a finite number
};
ParsedNumber parseDecimal(std::string_view text);
std::string_view trimSpaces(std::string_view text);
[[noreturn]] void throwNumberError(const std::string& what, std::string_view text,
                                   const std::string& problem);
std::string rangeText(long double min, long double max, bool integer);
std::optional<long long> parseSignedInteger(std::string_view text);
std::optional<unsigned long long> parseUnsignedInteger(std::string_view text);
}  // namespace detail

// `value` (already a double, e.g. from JSON) as a T in [min, max]; throws InputError naming `what`.
template <class T>
T checkedNumber(double value, const std::string& what, T min = std::numeric_limits<T>::lowest(),
                T max = std::numeric_limits<T>::max()) {
  static_assert(std::is_arithmetic_v<T>);
  const auto shown = [&] {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return std::string(buffer);
  };
  if (!std::isfinite(value)) detail::throwNumberError(what, shown(), "is not a finite number");
  if constexpr (std::is_integral_v<T>) {
    if (value != std::floor(value)) detail::throwNumberError(what, shown(), "is not a whole number");
  }
  if (static_cast<long double>(value) < static_cast<long double>(min) ||
      static_cast<long double>(value) > static_cast<long double>(max)) {
    detail::throwNumberError(what, shown(),
                             "is outside " + detail::rangeText(min, max, std::is_integral_v<T>));
  }
  return static_cast<T>(value);
}

// The number `text` holds, as a T in [min, max] (spaces around it are allowed, nothing else).
template <class T>
T parseNumber(std::string_view text, const std::string& what, T min = std::numeric_limits<T>::lowest(),
              T max = std::numeric_limits<T>::max()) {
  static_assert(std::is_arithmetic_v<T>);
  const detail::ParsedNumber parsed = detail::parseDecimal(text);
  if (!parsed.problem.empty() && !(std::is_integral_v<T> && parsed.integerText))
    detail::throwNumberError(what, text, parsed.problem);
  if constexpr (std::is_integral_v<T>) {
    // Whole numbers beyond 2^53 lose digits in a double: compare them as integers.
    if (parsed.integerText) {
      const std::string_view digits = detail::trimSpaces(text);
      if constexpr (std::is_signed_v<T>) {
        const auto exact = detail::parseSignedInteger(digits);
        if (exact && *exact >= static_cast<long long>(min) && *exact <= static_cast<long long>(max))
          return static_cast<T>(*exact);
      } else {
        const auto exact = detail::parseUnsignedInteger(digits);
        if (exact && *exact >= static_cast<unsigned long long>(min) &&
            *exact <= static_cast<unsigned long long>(max))
          return static_cast<T>(*exact);
      }
      detail::throwNumberError(what, text, "is outside " + detail::rangeText(min, max, true));
    }
  }
  try {
    return checkedNumber<T>(parsed.value, what, min, max);
  } catch (const std::exception&) {
    // Report the text as the user wrote it rather than its double.
    if constexpr (std::is_integral_v<T>) {
      if (parsed.value != std::floor(parsed.value))
        detail::throwNumberError(what, text, "is not a whole number");
    }
    detail::throwNumberError(what, text, "is outside " + detail::rangeText(min, max, std::is_integral_v<T>));
  }
}

}  // namespace kerf
