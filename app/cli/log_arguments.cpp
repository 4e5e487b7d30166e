// Arguments shared by the commands that take a log (log_arguments.hpp).
#include "log_arguments.hpp"

#include <stdexcept>

#include "io/log_data_import.hpp"
#include "util/error.hpp"

namespace kerf::cli {

// "random:SEED" or a path (Kerf log file or Gran_1 folder).
LogModel loadLogArgument(const std::string& text) {
  const std::string prefix = "random:";
  if (text.rfind(prefix, 0) == 0) {
    RandomLogOptions options;
    try {
      options.seed = static_cast<std::uint32_t>(std::stoul(text.substr(prefix.size())));
    } catch (const std::exception&) {
      throw InputError("LOG random:SEED needs a whole number seed, got \"" + text + "\"");
    }
    return generateRandomLog(options);
  }
  return loadLog(text);
}

void applySetting(WoodParameters& params, const std::string& setting) {
  const auto eq = setting.find('=');
  const std::string id = setting.substr(0, eq);
  const auto index = parameterIndex(id);
  if (eq == std::string::npos || !index) {
    throw InputError("--set takes id=value with a parameter id of `kerf-cli params`, got \"" + setting +
                     "\"");
  }
  const auto values = params.components(*index);
  std::string rest = setting.substr(eq + 1);
  for (std::size_t c = 0; c < values.size(); ++c) {
    const auto comma = rest.find(',');
    try {
      values[c] = std::stof(rest.substr(0, comma));
    } catch (const std::exception&) {
      throw InputError("--set " + id + " needs " + std::to_string(values.size()) + " number(s)");
    }
    rest = comma == std::string::npos ? std::string() : rest.substr(comma + 1);
  }
  validate(params);
}

}  // namespace kerf::cli
