#pragma once
// One output guard for every writer (issue 21), applied by io/atomic_file.* (writeFileAtomically,
// temporaryFileFor, replaceWithTemporary), so no writer can skip it:
// - an existing output must be a regular file: a FIFO, a device node (/dev/null) or a folder is refused,
//   never replaced by a regular file;
// - a symbolic link is written through: the file it points to is replaced, the link stays a link;
// - a read-only file (no write bit) is refused with a message, not replaced;
// - a replaced file keeps its permission bits (a 0600 project stays 0600);
// - in kerf-cli (refuseOutputsOverInputs), an output that is one of the files the command read (every
//   file opened through io/input_file.hpp is remembered) is refused: `rectify P --out P` must not
//   replace the photo. The editor saves over the project it opened, so it does not turn this on.
#include <filesystem>

namespace kerf {

// Where `target` is really written (a symbolic link's file), after the checks above; throws InputError.
std::filesystem::path checkedOutputTarget(const std::filesystem::path& target);

// Gives `temporary` the permission bits of `existing` if that exists (before it replaces it).
void keepPermissions(const std::filesystem::path& existing, const std::filesystem::path& temporary);

// Called by the safe input open: the file (its device and inode) is one of this process's inputs.
void rememberInputFile(const std::filesystem::path& path);

// kerf-cli turns this on: outputs that are inputs of the same command are refused.
void refuseOutputsOverInputs(bool on);

}  // namespace kerf
