#pragma once
// kerf-cli's outputs checked before a command runs (issue 21): two output options naming the same file
// (`render-board --out x.png --save-log x.png`), or an output that is a file given to another option or
// argument (`export --mesh m.obj --out m.obj`, `rectify P --out P`), are refused with exit code 2 before
// any work. Inputs found inside folders (a sample folder's photos) are caught when written, by the output
// guard (io/output_guard.hpp).
#include <CLI/CLI.hpp>

namespace kerf::cli {

// Throws InputError naming the options and the file.
void checkOutputsAgainstInputs(const CLI::App& command);

}  // namespace kerf::cli
