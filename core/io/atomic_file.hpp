#pragma once
// Atomic file replacement: write a temporary file next to the target, then rename it over the target,
// so a crash or an error never leaves a half-written file where a good one was.
#include <filesystem>
#include <functional>
#include <string_view>

namespace kerf {

// Calls write(temporaryPath); on success renames the temporary file to `target`, on any exception
// removes it and rethrows. The temporary file keeps the target's extension (some writers need it), is
// hidden (".NAME.tmpPID-N.EXT"); if a kill leaves it, the next write into the same folder (of any file)
// removes it, as every temporary there whose process PID no longer exists.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path& temporary)>& write);

// The temporary file writeFileAtomically uses, for writers that stream into it themselves and rename it
// when done (NRRD volumes); removes killed writers' leftovers in the target's folder first. Throws InputError
// when the target's folder does not exist, or the output guard (io/output_guard.hpp) refuses it.
std::filesystem::path temporaryFileFor(const std::filesystem::path& target);

// Renames a finished temporary over `target` (through a symbolic link to its file), keeping the
// existing file's permission bits. The output guard (io/output_guard.hpp) is checked again first.
void replaceWithTemporary(const std::filesystem::path& temporary, const std::filesystem::path& target);

// Creates an output folder and its parents if needed. Throws InputError "cannot create the folder X: why".
void createOutputFolder(const std::filesystem::path& folder);

// Convenience: atomically writes text.
void writeTextAtomically(const std::filesystem::path& target, std::string_view text);

}  // namespace kerf
