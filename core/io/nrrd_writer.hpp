#pragma once
// Streaming writer of NRRD volumes (teem's "nearly raw raster data": a short text header followed by
// raw little-endian samples). Written by hand because the format is ~15 header lines and the Debian
// libraries that read it (ITK, teem) cannot append a volume slice by slice. Axis order: see
// docs/volumes.md. The file appears atomically when finish() succeeds.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace kerf {

struct NrrdLayout {
  enum class Type { Float32, UInt8 } type = Type::Float32;
  int components = 1;    // 1 (scalar) or 3 (RGB colour, stored as the fastest axis)
  glm::ivec3 size{1};    // samples along x, y, z
  glm::vec3 spacing{1};  // mm between sample centres
  glm::vec3 origin{0};   // mm: centre of the first sample
  std::vector<std::pair<std::string, std::string>> keyValues;  // written as "key:=value"
  std::string comment;
};

class NrrdWriter {
 public:
  // Opens a temporary file next to `path` and writes the header. Throws InputError.
  NrrdWriter(const std::filesystem::path& path, const NrrdLayout& layout);
  ~NrrdWriter();
  NrrdWriter(const NrrdWriter&) = delete;
  NrrdWriter& operator=(const NrrdWriter&) = delete;

  // Appends the next z slice: size.x * size.y * components samples, x fastest.
  void writeSlice(std::span<const float> slice);
  void writeSlice(std::span<const std::uint8_t> slice);
  // Checks all slices were written, flushes and renames into place. Throws InputError.
  void finish();

 private:
  void writeBytes(const void* data, std::size_t bytes);

  std::filesystem::path path_, temporary_;
  NrrdLayout layout_;
  std::FILE* file_ = nullptr;
  int slicesWritten_ = 0;
};

// Parses the header of a NRRD file written by NrrdWriter (tests and re-import): returns the
// "field: value" and "key:=value" lines and the byte offset of the data.
struct NrrdHeader {
  std::vector<std::pair<std::string, std::string>> fields;
  std::vector<std::pair<std::string, std::string>> keyValues;
  std::size_t dataOffset = 0;
  std::string field(const std::string& name) const;
  std::string keyValue(const std::string& key) const;
};
NrrdHeader readNrrdHeader(const std::filesystem::path& path);

}  // namespace kerf
