#include "io/nrrd_writer.hpp"

#include <unistd.h>

#include <bit>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

static_assert(std::endian::native == std::endian::little, "NRRD writer assumes a little-endian machine");

std::string vectorText(glm::vec3 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << "," << v.y << "," << v.z << ")";
  return s.str();
}

}  // namespace

NrrdWriter::NrrdWriter(const std::filesystem::path& path, const NrrdLayout& layout)
    : path_(path), layout_(layout) {
  if (layout.size.x < 1 || layout.size.y < 1 || layout.size.z < 1)
    throw InputError("volume size must be positive");
  // Hidden, named as writeFileAtomically names its temporaries: the next export of this file removes what
  // a killed one left.
  temporary_ = temporaryFileFor(path);
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (!file_) throw InputError("cannot create " + path.string());

  std::ostringstream h;
  h.precision(9);
  const bool rgb = layout.components == 3;
  h << "NRRD0004\n";
  if (!layout.comment.empty()) h << "# " << layout.comment << "\n";
  h << "type: " << (layout.type == NrrdLayout::Type::Float32 ? "float" : "uint8") << "\n";
  h << "dimension: " << (rgb ? 4 : 3) << "\n";
  h << "space dimension: 3\n";
  h << "sizes: " << (rgb ? "3 " : "") << layout.size.x << " " << layout.size.y << " " << layout.size.z
    << "\n";
  h << "space directions: " << (rgb ? "none " : "") << vectorText({layout.spacing.x, 0, 0}) << " "
    << vectorText({0, layout.spacing.y, 0}) << " " << vectorText({0, 0, layout.spacing.z}) << "\n";
  h << "space origin: " << vectorText(layout.origin) << "\n";
  h << "space units: \"mm\" \"mm\" \"mm\"\n";
  h << "kinds: " << (rgb ? "RGB-color " : "") << "domain domain domain\n";
  h << "endian: little\n";
  h << "encoding: raw\n";
  for (const auto& [key, value] : layout.keyValues) h << key << ":=" << value << "\n";
  h << "\n";
  const std::string header = h.str();
  writeBytes(header.data(), header.size());
}

NrrdWriter::~NrrdWriter() {
  if (file_) {
    std::fclose(file_);
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void NrrdWriter::writeBytes(const void* data, std::size_t bytes) {
  if (std::fwrite(data, 1, bytes, file_) != bytes)
    throw InputError("cannot write " + path_.string() + " (disk full?)");
}

void NrrdWriter::writeSlice(std::span<const float> slice) {
  if (layout_.type != NrrdLayout::Type::Float32) throw std::logic_error("NRRD volume is not float");
  if (slice.size() != static_cast<std::size_t>(layout_.size.x) * layout_.size.y * layout_.components) {
    throw std::logic_error("NRRD slice has the wrong size");
  }
  writeBytes(slice.data(), slice.size_bytes());
  ++slicesWritten_;
}

void NrrdWriter::writeSlice(std::span<const std::uint8_t> slice) {
  if (layout_.type != NrrdLayout::Type::UInt8) throw std::logic_error("NRRD volume is not uint8");
  if (slice.size() != static_cast<std::size_t>(layout_.size.x) * layout_.size.y * layout_.components) {
    throw std::logic_error("NRRD slice has the wrong size");
  }
  writeBytes(slice.data(), slice.size_bytes());
  ++slicesWritten_;
}

void NrrdWriter::finish() {
  if (slicesWritten_ != layout_.size.z) throw std::logic_error("NRRD volume is missing slices");
  const bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  std::fclose(file_);
  file_ = nullptr;
  std::error_code error;
  if (!ok) {
    std::filesystem::remove(temporary_, error);
    throw InputError("cannot write " + path_.string());
  }
  try {
    replaceWithTemporary(temporary_, path_);  // the output guard, the link's file, the file's mode
  } catch (...) {
    std::filesystem::remove(temporary_, error);
    throw;
  }
}

std::string NrrdHeader::field(const std::string& name) const {
  for (const auto& [k, v] : fields)
    if (k == name) return v;
  return {};
}

std::string NrrdHeader::keyValue(const std::string& key) const {
  for (const auto& [k, v] : keyValues)
    if (k == key) return v;
  return {};
}

NrrdHeader readNrrdHeader(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open " + path.string());
  NrrdHeader header;
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0)
    throw InputError(path.string() + " is not a NRRD file");
  while (std::getline(in, line)) {
    if (line.empty()) break;
    if (line[0] == '#') continue;
    if (const auto kv = line.find(":="); kv != std::string::npos) {
      header.keyValues.emplace_back(line.substr(0, kv), line.substr(kv + 2));
    } else if (const auto colon = line.find(": "); colon != std::string::npos) {
      header.fields.emplace_back(line.substr(0, colon), line.substr(colon + 2));
    } else {
      throw InputError("malformed NRRD header line: " + line);
    }
  }
  header.dataOffset = static_cast<std::size_t>(in.tellg());
  return header;
}

}  // namespace kerf
