#include "io/json_file.hpp"

#include "io/input_file.hpp"

namespace kerf {

nlohmann::json readJsonFile(const std::filesystem::path& path, const std::string& kind) {
  return parseJsonText(readInputFile(path, kind, kMaxJsonFileBytes), kind + " " + path.string());
}

}  // namespace kerf
