#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>

#include "util/error.hpp"

namespace kerf {

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& write) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
  if (!std::filesystem::is_directory(folder)) {
    throw InputError("cannot write " + target.string() + ": folder " + folder.string() + " does not exist");
  }
  const std::filesystem::path temporary =
      folder / ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + "-" +
                std::to_string(counter++) + target.extension().string());
  try {
    write(temporary);
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) throw InputError("cannot replace " + target.string() + ": " + error.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void writeTextAtomically(const std::filesystem::path& target, std::string_view text) {
  writeFileAtomically(target, [&](const std::filesystem::path& temporary) {
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw InputError("cannot create " + temporary.string());
    const bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size() && std::fflush(file) == 0 &&
                    ::fsync(::fileno(file)) == 0;
    std::fclose(file);
    if (!ok) throw InputError("cannot write " + target.string() + " (disk full?)");
  });
}

}  // namespace kerf
