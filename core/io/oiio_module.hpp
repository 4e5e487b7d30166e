#pragma once
// Loads the OpenImageIO module (io/oiio_codecs.hpp) once, the first time a file other than PNG is read or
// written. Where: $KERF_OIIO_MODULE if set, else where this build put it, else next to the program.
#include <filesystem>

#include "io/oiio_codecs.hpp"

namespace kerf {

// Throws InputError naming `file` (the image that needed it) when the module cannot be loaded.
const OiioCodecs& oiioCodecs(const std::filesystem::path& file);

}  // namespace kerf
