#pragma once
// Every file format Kerf exports, in one table (issue 15 item 4). The writers' dispatch, the CLI's help
// and errors, and the editor's format boxes and file filters all read it: a new format is one row here
// plus its writer. docs/export.md describes each format.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

// What an export writes; the output path's extension picks it (a depth stack: a folder).
enum class ExportKind { Image, Volume, DepthStack, Part };

enum class ExportFormat { Png, Tiff, Exr, Nrrd, Vdb, Obj, Glb };

struct ExportFormatInfo {
  ExportFormat format;
  ExportKind kind;
  std::string_view name;                       // "TIFF"
  std::array<std::string_view, 2> extensions;  // lower case with the dot; the first is the one Kerf writes
  std::string_view summary;                    // what the file holds, for a format box: "16-bit colour; ..."
};

// The table, in the order the editor lists the formats of a kind.
const std::vector<ExportFormatInfo>& exportFormats();
std::vector<ExportFormatInfo> exportFormatsOf(ExportKind kind);
const ExportFormatInfo& exportFormatInfo(ExportFormat format);

// The format the path's extension names (any case), or nullopt.
std::optional<ExportFormatInfo> exportFormatOf(const std::filesystem::path& path);

// The extensions of one kind as a sentence lists them: ".png, .tif, .tiff or .exr".
std::string extensionList(ExportKind kind);
// The same, space-separated, for a compact help text: ".png .tif .tiff .exr".
std::string extensionWords(ExportKind kind);
// A file-dialog filter for one format: "TIFF (*.tif *.tiff)".
std::string fileFilter(const ExportFormatInfo& info);

// The format `path` names if it is of `kind`; otherwise InputError naming the path and, after `what`
// ("an image", "a volume", "a textured part"), the extensions that kind accepts.
ExportFormatInfo requireExportFormat(const std::filesystem::path& path, ExportKind kind,
                                     std::string_view what);

}  // namespace kerf
