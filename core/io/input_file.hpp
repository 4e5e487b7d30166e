#pragma once
// One safe way to open a user's input file (issue 21). Before anything is read: the path must name a
// regular file (following symbolic links): a FIFO would block the reader for ever, /dev/zero would feed it
// for ever, a folder or a device is no photo or project. Its size must be within the reader's budget.
// Errors are InputError naming the file and what it is instead.
#include <cstdint>
#include <filesystem>
#include <string>

namespace kerf {

// Budgets for the files Kerf reads whole. JSON grows with its content (a project with a log is about
// 0.5 MB); images are bounded again by their pixel count from the header (io/image.hpp).
inline constexpr std::uintmax_t kMaxJsonFileBytes = 256ull << 20;
inline constexpr std::uintmax_t kMaxImageFileBytes = 2ull << 30;
inline constexpr std::uintmax_t kMaxMeshFileBytes = 1ull << 30;

// What a file that is not a regular file is, for messages: "a pipe (FIFO)", "a character device", ...
const char* fileTypeName(unsigned mode);

// Throws InputError unless `path` is a regular file of at most `maxBytes`. `kind` names it ("photo").
// Returns its size.
std::uintmax_t checkInputFile(const std::filesystem::path& path, const std::string& kind,
                              std::uintmax_t maxBytes);

// The whole file as bytes, checked as above, opened without blocking (O_NONBLOCK) and checked again on
// the open descriptor, so a FIFO swapped in after the first check cannot block either.
std::string readInputFile(const std::filesystem::path& path, const std::string& kind,
                          std::uintmax_t maxBytes);

}  // namespace kerf
