// Arguments shared by the commands that take a log (log_arguments.hpp).
#include "log_arguments.hpp"

#include <stdexcept>

#include "io/log_data_import.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"
#include "util/parse_number.hpp"

namespace kerf::cli {

// "random:SEED" or a path (Kerf log file or Gran_1 folder).
LogModel loadLogArgument(const std::string& text) {
  const std::string prefix = "random:";
  if (text.rfind(prefix, 0) == 0) {
    RandomLogOptions options;
    options.seed = parseNumber<std::uint32_t>(text.substr(prefix.size()), "LOG random:SEED");
    return generateRandomLog(options);
  }
  return loadLog(text);
}

void applySetting(WoodParameters& params, const std::string& setting) {
  const auto eq = setting.find('=');
  const std::string id = setting.substr(0, eq);
  const auto index = parameterIndex(id);
  if (eq == std::string::npos || !index) {
    throw InputError("--set takes id=value with a parameter id of `kerf-cli params`, got " +
                     quoteForMessage(setting));
  }
  const auto values = params.components(*index);
  const std::string what = "--set " + id;
  const std::vector<float> numbers = parseNumberList(setting.substr(eq + 1), what);
  if (numbers.size() != values.size())
    throw InputError(what + " needs " + std::to_string(values.size()) + " number(s), got " +
                     std::to_string(numbers.size()));
  const bool integer = parameterSchema()[*index].kind == ParamKind::Integer;
  for (std::size_t c = 0; c < values.size(); ++c) {
    values[c] = integer ? static_cast<float>(checkedNumber<int>(numbers[c], what)) : numbers[c];
  }
  validate(params);
}

}  // namespace kerf::cli
