#pragma once
// Helpers shared by the fuzz targets: a scratch folder per process (the readers under test take paths),
// and the rule every target checks: a reader returns a value or throws kerf::InputError, nothing else.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "image/gray_image.hpp"

namespace kerf::fuzz {

// An empty folder in /dev/shm (in memory; /tmp where it is missing), fresh for each input.
inline std::filesystem::path freshScratch(const char* target) {
  namespace fs = std::filesystem;
  const fs::path root = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  const fs::path dir = root / (std::string("kerf-") + target + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline void writeBytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A property every reader's result must have; a violation is reported like a crash.
inline void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "kerf fuzz: property violated: %s\n", what);
    std::abort();
  }
}

inline bool finite(float v) {
  return std::isfinite(v);
}

}  // namespace kerf::fuzz
