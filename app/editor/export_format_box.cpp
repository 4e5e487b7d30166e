#include "export_format_box.hpp"

#include <QSignalBlocker>

namespace kerf {
namespace {

QString qs(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

}  // namespace

void addExportFormats(QComboBox* box, ExportKind kind) {
  for (const ExportFormatInfo& info : exportFormatsOf(kind))
    box->addItem(qs(info.name) + " (" + qs(info.summary) + ")", qs(info.extensions[0]));
}

bool selectExportFormatOf(QComboBox* box, const QString& path) {
  const std::optional<ExportFormatInfo> info = exportFormatOf(path.toStdString());
  if (!info) return false;
  const int index = box->findData(qs(info->extensions[0]));
  if (index < 0) return false;
  if (index != box->currentIndex()) {
    const QSignalBlocker block(box);
    box->setCurrentIndex(index);
  }
  return true;
}

QString selectedFormatFilter(const QComboBox* box) {
  std::string name = "x";  // a file name with the item's extension
  name += box->currentData().toString().toStdString();
  const std::optional<ExportFormatInfo> info = exportFormatOf(name);
  return info ? QString::fromStdString(fileFilter(*info)) : QString();
}

QString exportFormatFilters(ExportKind kind) {
  QStringList filters;
  for (const ExportFormatInfo& info : exportFormatsOf(kind))
    filters << QString::fromStdString(fileFilter(info));
  return filters.join(";;");
}

}  // namespace kerf
