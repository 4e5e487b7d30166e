#pragma once
// The editor's side of the export-format table (core/export/export_formats.hpp): a format box lists a
// kind's formats from the table, a typed path selects its format, and the file dialog filters by it.
#include <QComboBox>
#include <QString>

#include "export/export_formats.hpp"

namespace kerf {

// Fills `box` with the formats of `kind`: "TIFF (16-bit colour; ...)", the item's data the extension
// Kerf writes (".tif").
void addExportFormats(QComboBox* box, ExportKind kind);

// Selects the item of the format `path`'s extension names (".tiff" selects TIFF) without signals; false
// when the path names no format of the box.
bool selectExportFormatOf(QComboBox* box, const QString& path);

// The file-dialog filter of the selected format: "TIFF (*.tif *.tiff)".
QString selectedFormatFilter(const QComboBox* box);
// The filters of every format of `kind`, one per format: "OBJ (*.obj);;glTF binary (*.glb)".
QString exportFormatFilters(ExportKind kind);

}  // namespace kerf
