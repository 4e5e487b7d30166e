#include "io/output_guard.hpp"

#include <sys/stat.h>

#include <atomic>
#include <mutex>
#include <set>
#include <utility>

#include "io/input_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

std::atomic<bool> guardInputs{false};
std::mutex inputsMutex;
std::set<std::pair<dev_t, ino_t>> inputs;  // what this process read, by device and inode (hard links too)

}  // namespace

std::filesystem::path checkedOutputTarget(const std::filesystem::path& target) {
  std::filesystem::path real = target;
  std::error_code error;
  // A symbolic link (or a chain of them) is written through: replace the file it names, keep the link.
  if (std::filesystem::is_symlink(target, error)) {
    real = std::filesystem::weakly_canonical(target, error);
    if (error)
      throw InputError("cannot write " + target.string() + ": cannot follow the link (" + error.message() +
                       ")");
  }
  struct stat st {};
  if (::stat(real.c_str(), &st) != 0) return real;  // a new file
  if (!S_ISREG(st.st_mode))
    throw InputError("cannot write " + target.string() + ": it is " + fileTypeName(st.st_mode) +
                     "; Kerf writes only regular files and does not replace anything else");
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
    throw InputError(
        "cannot write " + target.string() +
        ": the file is read-only; Kerf does not replace read-only files (make it writable first, "
        "or choose another name)");
  if (guardInputs) {
    const std::lock_guard lock(inputsMutex);
    if (inputs.count({st.st_dev, st.st_ino}))
      throw InputError("cannot write " + target.string() +
                       ": it is also an input of this command; choose another output name");
  }
  return real;
}

void keepPermissions(const std::filesystem::path& existing, const std::filesystem::path& temporary) {
  struct stat st {};
  if (::stat(existing.c_str(), &st) == 0 && S_ISREG(st.st_mode))
    ::chmod(temporary.c_str(), st.st_mode & 07777);
}

void rememberInputFile(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  const std::lock_guard lock(inputsMutex);
  inputs.insert({st.st_dev, st.st_ino});
}

void refuseOutputsOverInputs(bool on) {
  guardInputs = on;
}

}  // namespace kerf
