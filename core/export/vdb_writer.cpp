#include "export/vdb_writer.hpp"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <mutex>

#include "io/atomic_file.hpp"
#include "util/error.hpp"

namespace kerf {

struct VdbWriter::Grid {
  openvdb::FloatGrid::Ptr growth;  // one of the two
  openvdb::Vec3SGrid::Ptr color;
  openvdb::GridBase::Ptr base() const {
    return growth ? openvdb::GridBase::Ptr(growth) : openvdb::GridBase::Ptr(color);
  }
};

VdbWriter::VdbWriter(const std::filesystem::path& path, const NrrdLayout& layout)
    : path_(path), layout_(layout), grid_(std::make_unique<Grid>()) {
  static std::once_flag initialized;
  std::call_once(initialized, [] { openvdb::initialize(); });
  if (layout.size.x < 1 || layout.size.y < 1 || layout.size.z < 1)
    throw InputError("volume size must be positive");
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  if (!std::filesystem::is_directory(folder)) {
    throw InputError("cannot write " + path.string() + ": folder " + folder.string() + " does not exist");
  }
  openvdb::GridBase::Ptr grid;
  if (layout.type == NrrdLayout::Type::Float32 && layout.components == 1) {
    grid_->growth = openvdb::FloatGrid::create(0.0f);
    grid = grid_->growth;
  } else if (layout.type == NrrdLayout::Type::UInt8 && layout.components == 3) {
    grid_->color = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    grid_->color->setVectorType(openvdb::VEC_INVARIANT);
    grid_->color->setSaveFloatAsHalf(true);  // 8-bit colour loses nothing in half
    grid = grid_->color;
  } else {
    throw std::logic_error("VDB writer: float scalars or uint8 RGB only");
  }
  std::string name = "growth", units = grid_->growth ? "years" : "";
  for (const auto& [key, value] : layout.keyValues) {
    if (key == "quantity") name = value;
    if (key == "units") units = value;
    grid->insertMeta(key, openvdb::StringMetadata(value));
  }
  grid->setName(name);
  if (!layout.comment.empty()) grid->insertMeta("description", openvdb::StringMetadata(layout.comment));
  grid->insertMeta(
      "units", openvdb::StringMetadata(units.empty() ? "world space in mm" : units + "; world space in mm"));
  // Index (i, j, k) -> origin + (i, j, k) * spacing: voxel centres at the samples' block coordinates.
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(1.0);
  transform->preScale(openvdb::Vec3d(layout.spacing.x, layout.spacing.y, layout.spacing.z));
  transform->postTranslate(openvdb::Vec3d(layout.origin.x, layout.origin.y, layout.origin.z));
  grid->setTransform(transform);
}

VdbWriter::~VdbWriter() = default;

void VdbWriter::writeSlice(std::span<const float> slice) {
  if (!grid_->growth) throw std::logic_error("VDB volume is not float");
  if (slice.size() != static_cast<std::size_t>(layout_.size.x) * layout_.size.y)
    throw std::logic_error("VDB slice has the wrong size");
  auto accessor = grid_->growth->getAccessor();
  const int z = slicesWritten_++;
  for (int y = 0; y < layout_.size.y; ++y)
    for (int x = 0; x < layout_.size.x; ++x)
      accessor.setValueOn(openvdb::Coord(x, y, z), slice[static_cast<std::size_t>(y) * layout_.size.x + x]);
}

void VdbWriter::writeSlice(std::span<const std::uint8_t> slice) {
  if (!grid_->color) throw std::logic_error("VDB volume is not RGB");
  if (slice.size() != static_cast<std::size_t>(layout_.size.x) * layout_.size.y * 3)
    throw std::logic_error("VDB slice has the wrong size");
  auto accessor = grid_->color->getAccessor();
  const int z = slicesWritten_++;
  for (int y = 0; y < layout_.size.y; ++y)
    for (int x = 0; x < layout_.size.x; ++x) {
      const std::uint8_t* c = &slice[(static_cast<std::size_t>(y) * layout_.size.x + x) * 3];
      accessor.setValueOn(openvdb::Coord(x, y, z), openvdb::Vec3s(c[0], c[1], c[2]) / 255.0f);
    }
}

void VdbWriter::finish() {
  if (slicesWritten_ != layout_.size.z) throw std::logic_error("VDB volume is missing slices");
  writeFileAtomically(path_, [&](const std::filesystem::path& temporary) {
    try {
      openvdb::io::File file(temporary.string());
      if (openvdb::io::Archive::hasBloscCompression())
        file.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
      openvdb::MetaMap meta;
      meta.insertMeta("generator", openvdb::StringMetadata("Kerf"));
      file.write({grid_->base()}, meta);
      file.close();
    } catch (const openvdb::Exception& e) {
      throw InputError("cannot write " + path_.string() + ": " + e.what());
    }
  });
}

}  // namespace kerf
