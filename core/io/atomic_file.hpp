#pragma once
// Atomic file replacement: write a temporary file next to the target, then rename it over the target,
// so a crash or an error never leaves a half-written file where a good one was.
#include <filesystem>
#include <functional>
#include <string_view>

namespace kerf {

// Calls write(temporaryPath); on success renames the temporary file to `target`, on any exception
// removes it and rethrows. The temporary file keeps the target's extension (some writers need it).
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path& temporary)>& write);

// Convenience: atomically writes text.
void writeTextAtomically(const std::filesystem::path& target, std::string_view text);

}  // namespace kerf
