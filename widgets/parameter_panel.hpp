#pragma once
// The parameter panel: every procedural parameter of the wood model as an editable row, built
// entirely from the parameter schema (core/params/wood_parameters.def); no per-parameter code.
//
// Layout, top to bottom: a species preset box, a filter field, then one collapsible section per schema
// group (growth, rings, colour, ...) with one row per parameter:
//   Scalar   label | slider over the soft range | number field (unit suffix, up to the hard range) | reset
//   Integer  label | "New random" button               | whole-number field                       | reset
//   Colour   label | colour swatch (opens a picker)    | hex field                                | reset
//   Colour beyond 0..1 (face tints): label | three multiplier fields R, G, B | swatch              | reset
//   Vector3  label | three fields x, y, z (unit suffix)                                          | reset
// Sliders map linearly or logarithmically as the schema's `scale` column says (Log for sizes and
// durations whose soft range spans a factor of 20 or more, so both ends of the travel are usable). A value
// typed outside the soft range is kept; the slider then rests at its end.
//
// Edits are reported, never applied to a document: parameterEdited(index, value, finished) with
// `finished` false for every intermediate value of a slider drag (and of a colour being browsed in the
// picker), true on slider release, keyboard steps, a committed number, a picked colour or a reset.
#include <QString>
#include <QWidget>
#include <array>
#include <memory>
#include <vector>

#include "params/parameter_schema.hpp"
#include "params/presets.hpp"

class QComboBox;
class QLineEdit;
class QScrollArea;

namespace kerf {

class ParameterPanel : public QWidget {
  Q_OBJECT

 public:
  // Lists builtInPresets() in the preset box.
  explicit ParameterPanel(QWidget* parent = nullptr);
  ~ParameterPanel() override;

  // Shows `params` in every row without emitting anything. Only rows whose value changed are touched;
  // no widget is created or destroyed.
  void setParameters(const WoodParameters& params);
  // The values as shown (the last setParameters plus the user's edits since).
  const WoodParameters& parameters() const { return params_; }

  // The presets offered in the preset box (sorted as given).
  void setPresets(const std::vector<Preset>& presets);
  // Shows `presetId` as the current preset without emitting; empty (or unknown) shows none.
  void setCurrentPreset(const QString& presetId);
  QString currentPreset() const;

  void setFilterText(const QString& text);
  QString filterText() const;
  void setSectionExpanded(const QString& group, bool expanded);
  bool isSectionExpanded(const QString& group) const;

  // Rows in schema order (index into parameterSchema()), for the editor and tests.
  int rowCount() const { return static_cast<int>(rows_.size()); }
  QWidget* row(int index) const;
  // Whether the row passes the filter (it may still be scrolled out of view or in a collapsed section).
  bool rowMatchesFilter(int index) const;
  QLineEdit* filterField() const { return filter_; }
  QComboBox* presetBox() const { return presetBox_; }

  // Wide enough for every row (a dock cannot squeeze the fields); tall enough for a few rows.
  QSize minimumSizeHint() const override;
  QSize sizeHint() const override;

  // The schema's title of a group ("pores" -> "Pores (vessels)"); an unknown group capitalised.
  static QString groupTitle(const QString& group);

 signals:
  void parameterEdited(int index, std::array<float, 3> value, bool finished);
  void presetChosen(QString presetId);

 private:
  struct Row;
  struct Section;

  void buildRow(Row& row, QWidget* parent);
  void showValue(Row& row);  // widgets <- row value, without emitting
  void commit(Row& row, std::array<float, 3> value, bool finished);
  void onSliderMoved(Row& row, int position);
  void onSliderReleased(Row& row);
  void pickColor(Row& row);
  void applyFilter();
  void updateSection(Section& section);

  WoodParameters params_;
  std::vector<std::unique_ptr<Row>> rows_;
  std::vector<std::unique_ptr<Section>> sections_;
  std::vector<Preset> presets_;
  QComboBox* presetBox_ = nullptr;
  QLineEdit* filter_ = nullptr;
  QScrollArea* scroll_ = nullptr;
  int labelWidth_ = 0;
  int fieldWidth_ = 0;
};

}  // namespace kerf
