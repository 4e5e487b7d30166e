#include "io/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "io/output_guard.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

// ".NAME.tmp": the start of every temporary of `target` (built with append: GCC 12 warns falsely about
// "." + string, -Wrestrict).
std::string temporaryPrefix(const std::filesystem::path& target) {
  std::string prefix(".");
  prefix.append(target.stem().string()).append(".tmp");
  return prefix;
}

// The process id in a name of Kerf's temporary pattern ".NAME.tmpPID-N" or ".NAME.tmpPID-N.EXT" (files,
// and the staging folders of detect), or 0 for any other name.
long temporaryOwner(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return 0;
  for (std::size_t at = name.find(".tmp", 1); at != std::string::npos; at = name.find(".tmp", at + 1)) {
    const std::size_t digits = at + 4, dash = name.find_first_not_of("0123456789", digits);
    if (dash == digits || dash == std::string::npos || name[dash] != '-') continue;
    const std::size_t counter = dash + 1, end = name.find_first_not_of("0123456789", counter);
    if (end == counter || (end != std::string::npos && name[end] != '.')) continue;
    return std::strtol(name.c_str() + digits, nullptr, 10);
  }
  return 0;
}

// A process killed while writing (SIGKILL, a power cut) leaves its hidden temporary behind: up to a whole
// volume's size (issue 21: 50 MB after a killed export-volume). Every write sweeps its folder and removes
// the temporaries, of any target, whose process no longer exists; a live writer's (another Kerf writing
// there right now) is left alone. A process id that was reused keeps its leftover until the id is free.
void removeStaleTemporaries(const std::filesystem::path& folder) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const long pid = temporaryOwner(it->path().filename().string());
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    std::filesystem::remove_all(it->path(), ignored);
  }
}

}  // namespace

std::filesystem::path temporaryFileFor(const std::filesystem::path& requested) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target = checkedOutputTarget(requested);
  const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
  if (!std::filesystem::is_directory(folder)) {
    throw InputError("cannot write " + target.string() + ": folder " + folder.string() + " does not exist");
  }
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError("cannot write " + target.string() + ": folder " + folder.string() +
                     " is not writable (" + std::strerror(errno) + ")");
  removeStaleTemporaries(folder);
  return folder / (temporaryPrefix(target) + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                   target.extension().string());
}

void replaceWithTemporary(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  const std::filesystem::path real = checkedOutputTarget(target);  // again: a link's file, not the link
  keepPermissions(real, temporary);
  std::error_code error;
  std::filesystem::rename(temporary, real, error);
  if (error) throw InputError("cannot replace " + target.string() + ": " + error.message());
}

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path temporary = temporaryFileFor(target);
  try {
    write(temporary);
    replaceWithTemporary(temporary, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void createOutputFolder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw InputError("cannot create the folder " + folder.string() + ": " +
                     (error ? error.message() : std::string("a file of that name is in the way")));
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
