# Writes a C++ source holding the bytes of the shipped ring detector network
# (resources/models/ring_detector.onnx), so the core has it built in. Run by core/CMakeLists.txt:
#   cmake -DOUT=<file.cpp> -DMODEL=<file.onnx> -P embed_model.cmake
file(READ "${MODEL}" hex HEX)
string(LENGTH "${hex}" length)
math(EXPR bytes "${length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
string(REGEX REPLACE "((0x..,){32})" "\\1\n" body "${body}")
file(WRITE "${OUT}.new" "// Generated from resources/models/ring_detector.onnx by core/rings/embed_model.cmake; do not edit.
#include \"rings/learned_ring_detector.hpp\"

namespace kerf {
namespace {
alignas(16) const unsigned char kModel[${bytes}] = {
${body}};
}  // namespace

std::span<const std::byte> builtInRingDetectorModel() {
  return {reinterpret_cast<const std::byte*>(kModel), sizeof kModel};
}

}  // namespace kerf
")
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.new")
