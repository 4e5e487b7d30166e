#include "util/parse_number.hpp"

#include <cctype>
#include <charconv>
#include <system_error>

#include "util/error.hpp"

namespace kerf {

std::string quoteForMessage(std::string_view text, std::size_t maxChars) {
  std::string shown;
  for (const char c : text.substr(0, maxChars)) {
    // Binary bytes (a photo given as a project) would garble the terminal: show them as '?'.
    shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  if (text.size() > maxChars) return "\"" + shown + "...\" (" + std::to_string(text.size()) + " characters)";
  return "\"" + shown + "\"";
}

namespace detail {

std::string_view trimSpaces(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

ParsedNumber parseDecimal(std::string_view text) {
  ParsedNumber out;
  std::string_view t = trimSpaces(text);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars takes '-' only
  if (t.empty()) {
    out.problem = "is not a number";
    return out;
  }
  // Decimal only: "0x10" and "010" must not mean 16 and 8 (strtol with base 0 did that).
  const char* begin = t.data();
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(begin, end, out.value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    out.problem = "is too large or too small for a number";
  } else if (ec != std::errc() || ptr != end) {
    out.problem = "is not a number";
  } else if (!std::isfinite(out.value)) {
    out.problem = "is not a finite number";  // "nan", "inf", "infinity"
  }
  std::string_view digits = t;
  if (!digits.empty() && digits.front() == '-') digits.remove_prefix(1);
  out.integerText = !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
  return out;
}

std::optional<long long> parseSignedInteger(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

std::optional<unsigned long long> parseUnsignedInteger(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (!text.empty() && text.front() == '-') {
    // "-0" is zero; any other negative number is below every unsigned range.
    return text.find_first_not_of("0", 1) == std::string_view::npos ? std::optional(0ULL) : std::nullopt;
  }
  unsigned long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string rangeText(long double min, long double max, bool integer) {
  const auto show = [integer](long double v) {
    char buffer[64];
    if (integer) {
      std::snprintf(buffer, sizeof buffer, "%.0Lf", v);
    } else {
      std::snprintf(buffer, sizeof buffer, "%.6Lg", v);
    }
    return std::string(buffer);
  };
  return std::string(integer ? "the whole numbers " : "") + "[" + show(min) + ", " + show(max) + "]";
}

void throwNumberError(const std::string& what, std::string_view text, const std::string& problem) {
  throw InputError(what + ": " + quoteForMessage(text) + " " + problem);
}

}  // namespace detail
}  // namespace kerf
