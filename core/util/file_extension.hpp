#pragma once
// The extension of an output path in lower case (".png", ".vdb", or "" when none): how the exporters pick
// a format.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace kerf {

inline std::string lowerExtension(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

}  // namespace kerf
