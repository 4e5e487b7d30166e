#include "export/export_formats.hpp"

#include <algorithm>

#include "util/error.hpp"
#include "util/file_extension.hpp"

namespace kerf {

const std::vector<ExportFormatInfo>& exportFormats() {
  static const std::vector<ExportFormatInfo> table = {
      {ExportFormat::Png, ExportKind::Image, "PNG", {".png", ""}, "8-bit, one layer"},
      {ExportFormat::Tiff,
       ExportKind::Image,
       "TIFF",
       {".tif", ".tiff"},
       "16-bit colour; growth and rings pages"},
      {ExportFormat::Exr,
       ExportKind::Image,
       "OpenEXR",
       {".exr", ""},
       "linear colour; growth and rings channels"},
      {ExportFormat::Nrrd, ExportKind::Volume, "NRRD", {".nrrd", ""}, "3D Slicer, ParaView, Fiji; streamed"},
      {ExportFormat::Vdb, ExportKind::Volume, "OpenVDB", {".vdb", ""}, "Blender, Houdini, ParaView"},
      {ExportFormat::Obj, ExportKind::Part, "OBJ", {".obj", ""}, "with MTL and PNG texture"},
      {ExportFormat::Glb, ExportKind::Part, "glTF binary", {".glb", ""}, "texture embedded"},
  };
  return table;
}

std::vector<ExportFormatInfo> exportFormatsOf(ExportKind kind) {
  std::vector<ExportFormatInfo> formats;
  for (const ExportFormatInfo& info : exportFormats())
    if (info.kind == kind) formats.push_back(info);
  return formats;
}

const ExportFormatInfo& exportFormatInfo(ExportFormat format) {
  const auto& table = exportFormats();
  return *std::find_if(table.begin(), table.end(),
                       [&](const ExportFormatInfo& info) { return info.format == format; });
}

std::optional<ExportFormatInfo> exportFormatOf(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  if (extension.empty()) return std::nullopt;
  for (const ExportFormatInfo& info : exportFormats())
    for (std::string_view e : info.extensions)
      if (e == extension) return info;
  return std::nullopt;
}

namespace {

std::vector<std::string_view> extensionsOf(ExportKind kind) {
  std::vector<std::string_view> all;
  for (const ExportFormatInfo& info : exportFormatsOf(kind))
    for (std::string_view e : info.extensions)
      if (!e.empty()) all.push_back(e);
  return all;
}

}  // namespace

std::string extensionList(ExportKind kind) {
  const std::vector<std::string_view> all = extensionsOf(kind);
  std::string text;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0) text += i + 1 == all.size() ? " or " : ", ";
    text += all[i];
  }
  return text;
}

std::string extensionWords(ExportKind kind) {
  std::string text;
  for (std::string_view e : extensionsOf(kind)) {
    if (!text.empty()) text += ' ';
    text += e;
  }
  return text;
}

std::string fileFilter(const ExportFormatInfo& info) {
  std::string patterns;
  for (std::string_view e : info.extensions)
    if (!e.empty()) {
      patterns += patterns.empty() ? "*" : " *";
      patterns += e;
    }
  return std::string(info.name) + " (" + patterns + ")";
}

ExportFormatInfo requireExportFormat(const std::filesystem::path& path, ExportKind kind,
                                     std::string_view what) {
  const std::optional<ExportFormatInfo> info = exportFormatOf(path);
  if (info && info->kind == kind) return *info;
  const std::string extension = lowerExtension(path);
  throw InputError("cannot write " + std::string(what) + " as \"" + extension + "\": " + path.string() +
                   " (use " + extensionList(kind) + ")");
}

}  // namespace kerf
