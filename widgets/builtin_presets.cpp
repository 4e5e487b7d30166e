#include "builtin_presets.hpp"

#include <QDir>
#include <QFile>
#include <QtDebug>
#include <algorithm>

#include "util/error.hpp"

namespace kerf {
namespace {

std::vector<Preset> readPresets() {
  std::vector<Preset> presets;
  const QDir dir(":/presets");
  for (const QString& name : dir.entryList({"*.json"}, QDir::Files, QDir::Name)) {
    QFile file(dir.filePath(name));
    if (!file.open(QIODevice::ReadOnly)) {
      qWarning() << "cannot read built-in preset" << name;
      continue;
    }
    const QByteArray bytes = file.readAll();
    try {
      const auto json = nlohmann::json::parse(bytes.constData(), bytes.constData() + bytes.size());
      Preset preset = presetFromJson(json);
      if (QString::fromStdString(preset.id) + ".json" != name) {
        throw InputError("its id \"" + preset.id + "\" does not match the file name");
      }
      presets.push_back(std::move(preset));
    } catch (const std::exception& e) {
      qWarning() << "built-in preset" << name << "left out:" << e.what();
    }
  }
  std::sort(presets.begin(), presets.end(), [](const Preset& a, const Preset& b) {
    return a.name != b.name ? a.name < b.name : a.id < b.id;
  });
  return presets;
}

}  // namespace

const std::vector<Preset>& builtInPresets() {
  static const std::vector<Preset> presets = readPresets();
  return presets;
}

const Preset* builtInPreset(const QString& id) {
  return findPreset(builtInPresets(), id.toStdString());
}

}  // namespace kerf
