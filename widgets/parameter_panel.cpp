#include "parameter_panel.hpp"

#include <QAbstractButton>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QRandomGenerator>
#include <QRegularExpressionValidator>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "params/builtin_presets.hpp"

namespace kerf {
namespace {

constexpr int kSliderSteps = 1000;

// Inside a scroll area the wheel scrolls the panel; a slider or field takes it only once focused, so
// scrolling past a row never changes a value by accident.
class PanelSlider : public QSlider {
 public:
  using QSlider::QSlider;

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (hasFocus()) {
      QSlider::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

class PanelDoubleSpinBox : public QDoubleSpinBox {
 public:
  using QDoubleSpinBox::QDoubleSpinBox;

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (hasFocus()) {
      QDoubleSpinBox::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

class PanelSpinBox : public QSpinBox {
 public:
  using QSpinBox::QSpinBox;

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (hasFocus()) {
      QSpinBox::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

// A clickable patch of colour.
class ColorSwatch : public QAbstractButton {
 public:
  explicit ColorSwatch(QWidget* parent) : QAbstractButton(parent) {
    setCursor(Qt::PointingHandCursor);
    setFocusPolicy(Qt::StrongFocus);
  }
  void setColor(const QColor& color) {
    if (color == color_) return;
    color_ = color;
    update();
  }
  QColor color() const { return color_; }
  QSize sizeHint() const override { return {48, 22}; }
  QSize minimumSizeHint() const override { return {24, 18}; }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF r = QRectF(rect()).adjusted(1.5, 2.5, -1.5, -2.5);
    const bool active = hasFocus() || underMouse();
    painter.setPen(
        QPen(active ? palette().highlight().color() : palette().mid().color(), active ? 2.0 : 1.0));
    painter.setBrush(color_);
    painter.drawRoundedRect(r, 3, 3);
  }
  void enterEvent(QEnterEvent* event) override {
    update();
    QAbstractButton::enterEvent(event);
  }
  void leaveEvent(QEvent* event) override {
    update();
    QAbstractButton::leaveEvent(event);
  }

 private:
  QColor color_ = Qt::white;
};

QString str(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString unitSuffix(std::string_view unit) {
  if (unit.empty()) return {};
  if (unit == "deg") return QStringLiteral("°");
  return QStringLiteral(" ") + str(unit);
}

QString formatNumber(double v) {
  if (std::abs(v) < 1e9 && v == std::round(v)) return QString::number(static_cast<qint64>(std::llround(v)));
  return QString::number(v, 'g', 6);
}

// 1, 2 or 5 times a power of ten, close to `raw`.
double niceStep(double raw) {
  if (!(raw > 0.0)) return 1.0;
  const double base = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / base;
  return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * base;
}

bool isLogarithmic(const ParamSpec& spec) {
  return spec.kind == ParamKind::Scalar && spec.scale == ParamScale::Log;
}

bool isMultiplierColor(const ParamSpec& spec) {
  return spec.kind == ParamKind::Color && spec.hardMax > 1.0f;
}

// Step of a field without a slider's help, and of a linear slider's keyboard step in value terms.
double linearStep(const ParamSpec& spec) {
  const double span = spec.softMax - spec.softMin;
  return niceStep(span / (spec.kind == ParamKind::Vector3 ? 400.0 : 100.0));
}

int decimalsFor(const ParamSpec& spec) {
  if (spec.kind == ParamKind::Integer) return 0;
  if (spec.kind == ParamKind::Color) return 2;
  int d;
  if (isLogarithmic(spec)) {
    d = static_cast<int>(std::ceil(-std::log10(spec.softMin) - 1e-9)) + 1;
  } else {
    const double step = linearStep(spec);
    d = step >= 1.0 ? 1 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  }
  return std::clamp(d, 0, 4);
}

int sliderPosition(const ParamSpec& spec, bool logScale, float value) {
  double t;
  if (logScale) {
    const double v = std::max<double>(value, spec.softMin);
    t = std::log(v / spec.softMin) / std::log(double(spec.softMax) / spec.softMin);
  } else {
    t = (double(value) - spec.softMin) / (double(spec.softMax) - spec.softMin);
  }
  if (!std::isfinite(t)) t = 0.0;
  return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

float sliderValue(const ParamSpec& spec, bool logScale, int decimals, int position) {
  const double t = double(position) / kSliderSteps;
  double v = logScale ? spec.softMin * std::pow(double(spec.softMax) / spec.softMin, t)
                      : spec.softMin + t * (double(spec.softMax) - spec.softMin);
  const double scale = std::pow(10.0, decimals);
  v = std::round(v * scale) / scale;
  return static_cast<float>(std::clamp(v, double(spec.hardMin), double(spec.hardMax)));
}

QColor toQColor(const std::array<float, 3>& v) {
  return QColor::fromRgbF(std::clamp(v[0], 0.0f, 1.0f), std::clamp(v[1], 0.0f, 1.0f),
                          std::clamp(v[2], 0.0f, 1.0f));
}

std::array<float, 3> fromQColor(const QColor& c) {
  return {c.red() / 255.0f, c.green() / 255.0f, c.blue() / 255.0f};
}

// Colours beyond 0..1 are multipliers (the face tints). Their swatch shows a light wood tone under the
// multiplier, and a colour picked for it is divided by that tone: "pick how light wood looks on this face".
constexpr std::array<float, 3> kReferenceWood = {0.80f, 0.62f, 0.42f};

QColor swatchColor(const ParamSpec& spec, const std::array<float, 3>& v) {
  if (spec.kind != ParamKind::Color || spec.hardMax <= 1.0f) return toQColor(v);
  return toQColor({v[0] * kReferenceWood[0], v[1] * kReferenceWood[1], v[2] * kReferenceWood[2]});
}

std::array<float, 3> pickedValue(const ParamSpec& spec, const QColor& color) {
  std::array<float, 3> v = fromQColor(color);
  if (spec.kind != ParamKind::Color || spec.hardMax <= 1.0f) return v;
  for (int k = 0; k < 3; ++k) {
    v[k] = std::clamp(std::round(100.0f * v[k] / kReferenceWood[k]) / 100.0f, spec.hardMin, spec.hardMax);
  }
  return v;
}

bool sameColor(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  return toQColor(a).rgb() == toQColor(b).rgb();
}

std::array<float, 3> defaultOf(const ParamSpec& spec) {
  return spec.defaultValue;
}

bool equalValues(const ParamSpec& spec, const std::array<float, 3>& a, const std::array<float, 3>& b) {
  for (int k = 0; k < spec.components(); ++k) {
    if (std::abs(a[k] - b[k]) > 1e-6f * std::max(1.0f, std::abs(b[k]))) return false;
  }
  return true;
}

QString valueText(const ParamSpec& spec, const std::array<float, 3>& v, int decimals) {
  const QString suffix = unitSuffix(spec.unit);
  switch (spec.kind) {
    case ParamKind::Scalar:
      return QString::number(v[0], 'f', decimals) + suffix;
    case ParamKind::Integer:
      return formatNumber(v[0]);
    case ParamKind::Color:
      if (isMultiplierColor(spec)) {
        return QStringLiteral("×%1, ×%2, ×%3").arg(v[0], 0, 'f', 2).arg(v[1], 0, 'f', 2).arg(v[2], 0, 'f', 2);
      }
      return toQColor(v).name();
    case ParamKind::Vector3:
      return QStringLiteral("(%1, %2, %3)%4")
          .arg(formatNumber(v[0]), formatNumber(v[1]), formatNumber(v[2]), suffix);
  }
  return {};
}

QString tooltipFor(const ParamSpec& spec, int decimals) {
  const QString suffix = unitSuffix(spec.unit);
  QString range;
  if (spec.kind == ParamKind::Color && !isMultiplierColor(spec)) {
    range = QObject::tr("Click the swatch to pick a colour, or type it as #rrggbb.");
  } else {
    const QString unitText =
        spec.kind == ParamKind::Color ? QObject::tr(" (multiplier per channel)") : suffix;
    range = QObject::tr("Slider: %1 – %2%3 · allowed: %4 – %5%3")
                .arg(formatNumber(spec.softMin), formatNumber(spec.softMax), unitText,
                     formatNumber(spec.hardMin), formatNumber(spec.hardMax));
    if (spec.kind == ParamKind::Integer || spec.kind == ParamKind::Vector3 || isMultiplierColor(spec)) {
      range = QObject::tr("Typical: %1 – %2%3 · allowed: %4 – %5%3")
                  .arg(formatNumber(spec.softMin), formatNumber(spec.softMax), unitText,
                       formatNumber(spec.hardMin), formatNumber(spec.hardMax));
    }
    if (isMultiplierColor(spec)) {
      range += QObject::tr(
          ". The swatch shows a light wood tone under this tint; click it to pick how that "
          "wood should look.");
    }
  }
  return QStringLiteral("<p><b>%1</b> <span style='color:gray'>%2</span></p><p>%3</p><p>%4<br>%5</p>")
      .arg(str(spec.label).toHtmlEscaped(), str(spec.id).toHtmlEscaped(), str(spec.tooltip).toHtmlEscaped(),
           range.toHtmlEscaped(),
           QObject::tr("Default: %1").arg(valueText(spec, defaultOf(spec), decimals)).toHtmlEscaped());
}

PanelDoubleSpinBox* makeField(const ParamSpec& spec, int decimals, QWidget* parent) {
  auto* field = new PanelDoubleSpinBox(parent);
  field->setDecimals(decimals);
  field->setRange(spec.hardMin, spec.hardMax);
  field->setKeyboardTracking(false);  // valueChanged on Enter, focus out or a step, not per keystroke
  field->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  field->setFocusPolicy(Qt::StrongFocus);
  field->setAccelerated(true);
  if (isLogarithmic(spec)) {
    field->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  } else {
    field->setSingleStep(spec.kind == ParamKind::Color ? 0.01 : linearStep(spec));
  }
  return field;
}

}  // namespace

struct ParameterPanel::Row {
  int index = 0;
  const ParamSpec* spec = nullptr;
  bool logScale = false;
  int decimals = 2;
  QWidget* widget = nullptr;
  QLabel* label = nullptr;
  QSlider* slider = nullptr;
  std::array<QDoubleSpinBox*, 3> fields{};
  QSpinBox* intField = nullptr;
  ColorSwatch* swatch = nullptr;
  QLineEdit* hex = nullptr;
  QToolButton* reset = nullptr;
  std::array<float, 3> value{};
  bool dragEmitted = false;
  QString searchText;
};

struct ParameterPanel::Section {
  QString group;
  QToolButton* header = nullptr;
  QWidget* body = nullptr;
  std::vector<int> rows;
  bool expanded = true;
  bool filterOpen = true;  // open/closed while a filter is active
};

QString ParameterPanel::groupTitle(const QString& group) {
  const std::string id = group.toStdString();
  const std::string_view title = parameterGroupTitle(id);
  if (!title.empty()) return str(title);
  QString fallback = group;
  if (!fallback.isEmpty()) fallback[0] = fallback[0].toUpper();
  return fallback;
}

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("parameterPanel"));
  const auto schema = parameterSchema();

  // Column widths shared by every row, so sliders and fields line up across sections.
  const QFontMetrics metrics(font());
  for (const ParamSpec& spec : schema) {
    labelWidth_ = std::max(labelWidth_, metrics.horizontalAdvance(str(spec.label)));
    if (spec.kind == ParamKind::Scalar) {
      const int d = decimalsFor(spec);
      for (float v : {spec.softMin, spec.softMax}) {
        fieldWidth_ = std::max(fieldWidth_,
                               metrics.horizontalAdvance(QString::number(v, 'f', d) + unitSuffix(spec.unit)));
      }
    }
  }
  labelWidth_ += 8;
  fieldWidth_ = std::max(fieldWidth_, metrics.horizontalAdvance(QStringLiteral("#000000"))) +
                metrics.horizontalAdvance(QStringLiteral("00"));

  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(6, 6, 6, 0);
  outer->setSpacing(6);

  // Preset box and filter.
  auto* presetRow = new QHBoxLayout;
  auto* presetLabel = new QLabel(tr("Preset:"), this);
  presetBox_ = new QComboBox(this);
  presetBox_->setObjectName(QStringLiteral("presetBox"));
  presetBox_->setPlaceholderText(tr("Choose a species…"));
  presetBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  presetBox_->setMinimumContentsLength(16);
  presetBox_->setToolTip(
      tr("Start from one of the species of the Mokume dataset. Sets the species' rings, colours, pores and "
         "rays; keeps where the pith lies, the face tints and the random seed of this block."));
  presetLabel->setBuddy(presetBox_);
  presetRow->addWidget(presetLabel);
  presetRow->addWidget(presetBox_, 1);
  outer->addLayout(presetRow);
  connect(presetBox_, &QComboBox::activated, this, [this](int index) {
    const QString id = presetBox_->itemData(index).toString();
    if (!id.isEmpty()) emit presetChosen(id);
  });

  filter_ = new QLineEdit(this);
  filter_->setObjectName(QStringLiteral("parameterFilter"));
  filter_->setPlaceholderText(tr("Filter parameters (Ctrl+F)"));
  filter_->setClearButtonEnabled(true);
  filter_->setToolTip(tr("Shows only the parameters whose name or id contains this text."));
  outer->addWidget(filter_);
  connect(filter_, &QLineEdit::textChanged, this, [this] {
    for (auto& section : sections_) section->filterOpen = true;
    applyFilter();
  });
  auto* find = new QShortcut(QKeySequence::Find, this);
  find->setContext(Qt::WidgetWithChildrenShortcut);
  connect(find, &QShortcut::activated, this, [this] {
    filter_->setFocus(Qt::ShortcutFocusReason);
    filter_->selectAll();
  });
  auto* clearFilter = new QShortcut(QKeySequence(Qt::Key_Escape), filter_);
  clearFilter->setContext(Qt::WidgetShortcut);
  connect(clearFilter, &QShortcut::activated, filter_, &QLineEdit::clear);

  // Sections and rows.
  auto* scroll = scroll_ = new QScrollArea(this);
  scroll->setObjectName(QStringLiteral("parameterScroll"));
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  auto* content = new QWidget(scroll);
  auto* contentLayout = new QVBoxLayout(content);
  contentLayout->setContentsMargins(0, 0, 4, 6);
  contentLayout->setSpacing(0);

  QFont headerFont = font();
  headerFont.setBold(true);
  rows_.reserve(schema.size());
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const QString group = str(schema[i].group);
    if (sections_.empty() || sections_.back()->group != group) {
      auto section = std::make_unique<Section>();
      section->group = group;
      section->expanded = group != QLatin1String("faces");  // per-photo tints: rarely touched by hand
      section->header = new QToolButton(content);
      section->header->setObjectName(QStringLiteral("section:") + group);
      section->header->setText(groupTitle(group));
      section->header->setFont(headerFont);
      section->header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
      section->header->setAutoRaise(true);
      section->header->setCheckable(true);
      section->header->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
      section->body = new QWidget(content);
      auto* bodyLayout = new QVBoxLayout(section->body);
      bodyLayout->setContentsMargins(4, 0, 0, 8);
      bodyLayout->setSpacing(2);
      contentLayout->addWidget(section->header);
      contentLayout->addWidget(section->body);
      Section* s = section.get();
      connect(section->header, &QToolButton::toggled, this, [this, s](bool on) {
        if (filter_->text().trimmed().isEmpty()) {
          s->expanded = on;
        } else {
          s->filterOpen = on;
        }
        updateSection(*s);
      });
      sections_.push_back(std::move(section));
    }
    Section& section = *sections_.back();
    auto row = std::make_unique<Row>();
    row->index = static_cast<int>(i);
    row->spec = &schema[i];
    buildRow(*row, section.body);
    section.body->layout()->addWidget(row->widget);
    section.rows.push_back(row->index);
    rows_.push_back(std::move(row));
  }
  contentLayout->addStretch(1);
  scroll->setWidget(content);
  outer->addWidget(scroll, 1);

  for (auto& row : rows_) {
    const auto v = params_.components(row->index);
    std::copy(v.begin(), v.end(), row->value.begin());
    showValue(*row);
  }
  for (auto& section : sections_) updateSection(*section);
  setPresets(builtInPresets());
}

ParameterPanel::~ParameterPanel() = default;

QSize ParameterPanel::minimumSizeHint() const {
  const QMargins margins = layout()->contentsMargins();
  const int width = scroll_->widget()->minimumSizeHint().width() +
                    scroll_->verticalScrollBar()->sizeHint().width() + margins.left() + margins.right();
  return {width, 240};
}

QSize ParameterPanel::sizeHint() const {
  return {std::max(minimumSizeHint().width(), 460), 760};
}

void ParameterPanel::buildRow(Row& row, QWidget* parent) {
  const ParamSpec& spec = *row.spec;
  const QString id = str(spec.id);
  row.logScale = isLogarithmic(spec);
  row.decimals = decimalsFor(spec);
  row.searchText = str(spec.label) + QLatin1Char(' ') + id;
  const QString tip = tooltipFor(spec, row.decimals);

  row.widget = new QWidget(parent);
  row.widget->setObjectName(QStringLiteral("row:") + id);
  auto* layout = new QHBoxLayout(row.widget);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(6);

  row.label = new QLabel(str(spec.label), row.widget);
  row.label->setFixedWidth(labelWidth_);
  row.label->setToolTip(tip);
  layout->addWidget(row.label);

  Row* r = &row;
  const auto connectField = [this, r](QDoubleSpinBox* field, int component) {
    connect(field, &QDoubleSpinBox::valueChanged, this, [this, r, component](double v) {
      std::array<float, 3> value = r->value;
      value[component] = static_cast<float>(v);
      if (value != r->value) commit(*r, value, true);
    });
  };

  switch (spec.kind) {
    case ParamKind::Scalar: {
      row.slider = new PanelSlider(Qt::Horizontal, row.widget);
      row.slider->setObjectName(QStringLiteral("slider:") + id);
      row.slider->setRange(0, kSliderSteps);
      row.slider->setSingleStep(kSliderSteps / 100);
      row.slider->setPageStep(kSliderSteps / 10);
      row.slider->setFocusPolicy(Qt::StrongFocus);
      row.slider->setMinimumWidth(60);
      row.slider->setToolTip(tip);
      layout->addWidget(row.slider, 1);
      connect(row.slider, &QSlider::valueChanged, this,
              [this, r](int position) { onSliderMoved(*r, position); });
      connect(row.slider, &QSlider::sliderPressed, this, [r] { r->dragEmitted = false; });
      connect(row.slider, &QSlider::sliderReleased, this, [this, r] { onSliderReleased(*r); });

      auto* field = makeField(spec, row.decimals, row.widget);
      field->setObjectName(QStringLiteral("field:") + id);
      field->setSuffix(unitSuffix(spec.unit));
      field->setButtonSymbols(QAbstractSpinBox::NoButtons);
      field->setFixedWidth(fieldWidth_);
      field->setToolTip(tip);
      layout->addWidget(field);
      row.fields[0] = field;
      connectField(field, 0);
      break;
    }
    case ParamKind::Integer: {
      auto* random = new QToolButton(row.widget);
      random->setObjectName(QStringLiteral("random:") + id);
      random->setText(tr("New random"));
      random->setToolTip(tr("Pick another random value: the same kind of wood, a different piece."));
      layout->addWidget(random);
      layout->addStretch(1);
      row.intField = new PanelSpinBox(row.widget);
      row.intField->setObjectName(QStringLiteral("field:") + id);
      row.intField->setRange(static_cast<int>(spec.hardMin), static_cast<int>(spec.hardMax));
      row.intField->setKeyboardTracking(false);
      row.intField->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
      row.intField->setFixedWidth(fieldWidth_);
      row.intField->setToolTip(tip);
      layout->addWidget(row.intField);
      connect(row.intField, &QSpinBox::valueChanged, this, [this, r](int v) {
        std::array<float, 3> value = r->value;
        value[0] = static_cast<float>(v);
        if (value != r->value) commit(*r, value, true);
      });
      connect(random, &QToolButton::clicked, this, [this, r] {
        const int lo = static_cast<int>(r->spec->softMin), hi = static_cast<int>(r->spec->softMax);
        std::array<float, 3> value = r->value;
        do {
          value[0] = static_cast<float>(QRandomGenerator::global()->bounded(lo, hi + 1));
        } while (value == r->value && hi > lo);
        commit(*r, value, true);
      });
      break;
    }
    case ParamKind::Color: {
      row.swatch = new ColorSwatch(row.widget);
      row.swatch->setObjectName(QStringLiteral("swatch:") + id);
      row.swatch->setToolTip(tip);
      connect(row.swatch, &QAbstractButton::clicked, this, [this, r] { pickColor(*r); });
      if (isMultiplierColor(spec)) {
        static const char* kChannels[] = {"R ", "G ", "B "};
        for (int k = 0; k < 3; ++k) {
          auto* field = makeField(spec, row.decimals, row.widget);
          field->setObjectName(QStringLiteral("field:%1:%2").arg(id).arg(k));
          field->setPrefix(QString::fromUtf8(kChannels[k]));
          field->setButtonSymbols(QAbstractSpinBox::NoButtons);
          field->setMinimumWidth(field->fontMetrics().horizontalAdvance(QStringLiteral("R 0.00")) + 12);
          field->setToolTip(tip);
          layout->addWidget(field, 1);
          row.fields[k] = field;
          connectField(field, k);
        }
        row.swatch->setFixedWidth(row.swatch->sizeHint().height() + 8);
        layout->insertWidget(1, row.swatch);  // between the label and the fields
      } else {
        layout->addWidget(row.swatch, 1);
        row.hex = new QLineEdit(row.widget);
        row.hex->setObjectName(QStringLiteral("hex:") + id);
        row.hex->setValidator(new QRegularExpressionValidator(
            QRegularExpression(QStringLiteral("#?[0-9a-fA-F]{0,6}")), row.hex));
        row.hex->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.hex->setFixedWidth(fieldWidth_);
        row.hex->setToolTip(tip);
        layout->addWidget(row.hex);
        connect(row.hex, &QLineEdit::editingFinished, this, [this, r] {
          QString text = r->hex->text().trimmed();
          if (!text.startsWith(QLatin1Char('#'))) text.prepend(QLatin1Char('#'));
          const QColor color(text);
          if (text.size() != 7 || !color.isValid() || sameColor(fromQColor(color), r->value)) {
            showValue(*r);  // back to the current colour, normalised
            return;
          }
          commit(*r, fromQColor(color), true);
        });
      }
      break;
    }
    case ParamKind::Vector3: {
      static const char* kAxes[] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        auto* field = makeField(spec, row.decimals, row.widget);
        field->setObjectName(QStringLiteral("field:%1:%2").arg(id).arg(k));
        field->setPrefix(QLatin1String(kAxes[k]) + QLatin1Char(' '));
        field->setButtonSymbols(QAbstractSpinBox::NoButtons);
        field->setMinimumWidth(field->fontMetrics().horizontalAdvance(QStringLiteral("x -00.0")) + 8);
        field->setToolTip(tip);
        layout->addWidget(field, 1);
        row.fields[k] = field;
        connectField(field, k);
      }
      if (!spec.unit.empty()) {  // the unit once, after the three fields
        auto* unit = new QLabel(unitSuffix(spec.unit).trimmed(), row.widget);
        unit->setToolTip(tip);
        layout->addWidget(unit);
      }
      break;
    }
  }

  row.reset = new QToolButton(row.widget);
  row.reset->setObjectName(QStringLiteral("reset:") + id);
  row.reset->setText(QStringLiteral("↺"));
  row.reset->setAutoRaise(true);
  row.reset->setToolTip(tr("Reset to the default (%1)").arg(valueText(spec, defaultOf(spec), row.decimals)));
  row.reset->setFocusPolicy(Qt::TabFocus);
  layout->addWidget(row.reset);
  connect(row.reset, &QToolButton::clicked, this, [this, r] { commit(*r, defaultOf(*r->spec), true); });
}

void ParameterPanel::showValue(Row& row) {
  const ParamSpec& spec = *row.spec;
  if (row.slider && !row.slider->isSliderDown()) {
    const QSignalBlocker block(row.slider);
    row.slider->setValue(sliderPosition(spec, row.logScale, row.value[0]));
  }
  for (int k = 0; k < 3; ++k) {
    if (!row.fields[k]) continue;
    const QSignalBlocker block(row.fields[k]);
    row.fields[k]->setValue(row.value[k]);
  }
  if (row.intField) {
    const QSignalBlocker block(row.intField);
    row.intField->setValue(static_cast<int>(std::lround(row.value[0])));
  }
  if (row.swatch) row.swatch->setColor(swatchColor(spec, row.value));
  if (row.hex) {
    const QSignalBlocker block(row.hex);
    row.hex->setText(toQColor(row.value).name());
  }
  row.reset->setEnabled(!equalValues(spec, row.value, defaultOf(spec)));
}

void ParameterPanel::commit(Row& row, std::array<float, 3> value, bool finished) {
  if (!finished && value == row.value) return;
  row.value = value;
  const auto target = params_.components(row.index);
  std::copy(value.begin(), value.begin() + target.size(), target.begin());
  showValue(row);
  emit parameterEdited(row.index, value, finished);
}

void ParameterPanel::onSliderMoved(Row& row, int position) {
  std::array<float, 3> value = row.value;
  value[0] = sliderValue(*row.spec, row.logScale, row.decimals, position);
  if (value == row.value) return;  // a step smaller than the field's precision
  if (row.slider->isSliderDown()) {
    row.dragEmitted = true;
    commit(row, value, false);
  } else {
    commit(row, value, true);  // keyboard, page step, wheel
  }
}

void ParameterPanel::onSliderReleased(Row& row) {
  if (!row.dragEmitted) return;
  row.dragEmitted = false;
  commit(row, row.value, true);
}

void ParameterPanel::pickColor(Row& row) {
  const std::array<float, 3> original = row.value;
  auto* dialog = new QColorDialog(swatchColor(*row.spec, original), this);
  dialog->setObjectName(QStringLiteral("colorDialog:") + str(row.spec->id));
  dialog->setWindowTitle(isMultiplierColor(*row.spec)
                             ? tr("%1: how light wood should look on this face").arg(str(row.spec->label))
                             : str(row.spec->label));
  dialog->setOption(QColorDialog::DontUseNativeDialog);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  Row* r = &row;
  const auto same = [r](const QColor& color, const std::array<float, 3>& value) {
    return color.rgb() == swatchColor(*r->spec, value).rgb();
  };
  // While browsing, the colour is previewed (finished = false); OK commits it, Cancel restores the original.
  auto previewed = std::make_shared<bool>(false);
  connect(dialog, &QColorDialog::currentColorChanged, this, [this, r, previewed, same](const QColor& color) {
    if (!color.isValid() || same(color, r->value)) return;
    *previewed = true;
    commit(*r, pickedValue(*r->spec, color), false);
  });
  connect(
      dialog, &QColorDialog::colorSelected, this, [this, r, original, previewed, same](const QColor& color) {
        if (!color.isValid()) return;
        const std::array<float, 3> value = same(color, original) ? original : pickedValue(*r->spec, color);
        if (value == original && !*previewed) return;
        commit(*r, value, true);
      });
  connect(dialog, &QDialog::rejected, this, [this, r, original, previewed] {
    if (*previewed) commit(*r, original, true);
  });
  dialog->open();
}

void ParameterPanel::setParameters(const WoodParameters& params) {
  params_ = params;
  for (auto& row : rows_) {
    const auto v = params.components(row->index);
    std::array<float, 3> value{};
    std::copy(v.begin(), v.end(), value.begin());
    if (value == row->value) continue;
    row->value = value;
    showValue(*row);
  }
}

void ParameterPanel::setPresets(const std::vector<Preset>& presets) {
  presets_ = presets;
  const QString current = currentPreset();
  const QSignalBlocker block(presetBox_);
  presetBox_->clear();
  for (const Preset& preset : presets_) {
    presetBox_->addItem(QString::fromStdString(preset.name), QString::fromStdString(preset.id));
    QString tip = QStringLiteral("<p><b>%1</b>").arg(QString::fromStdString(preset.name).toHtmlEscaped());
    if (!preset.latin.empty()) {
      tip += QStringLiteral(" <i>%1</i>").arg(QString::fromStdString(preset.latin).toHtmlEscaped());
    }
    if (!preset.mokumeCode.empty()) {
      tip += QStringLiteral(" · Mokume %1").arg(QString::fromStdString(preset.mokumeCode).toHtmlEscaped());
    }
    tip += QStringLiteral("</p><p>%1</p>").arg(QString::fromStdString(preset.description).toHtmlEscaped());
    presetBox_->setItemData(presetBox_->count() - 1, tip, Qt::ToolTipRole);
  }
  presetBox_->setCurrentIndex(presetBox_->findData(current));
}

void ParameterPanel::setCurrentPreset(const QString& presetId) {
  const QSignalBlocker block(presetBox_);
  presetBox_->setCurrentIndex(presetId.isEmpty() ? -1 : presetBox_->findData(presetId));
}

QString ParameterPanel::currentPreset() const {
  return presetBox_->currentIndex() < 0 ? QString() : presetBox_->currentData().toString();
}

void ParameterPanel::setFilterText(const QString& text) {
  filter_->setText(text);
}

QString ParameterPanel::filterText() const {
  return filter_->text();
}

void ParameterPanel::setSectionExpanded(const QString& group, bool expanded) {
  for (auto& section : sections_) {
    if (section->group == group) {
      section->expanded = expanded;
      updateSection(*section);
    }
  }
}

bool ParameterPanel::isSectionExpanded(const QString& group) const {
  for (const auto& section : sections_) {
    if (section->group == group) return section->expanded;
  }
  return false;
}

QWidget* ParameterPanel::row(int index) const {
  return index >= 0 && index < rowCount() ? rows_[index]->widget : nullptr;
}

bool ParameterPanel::rowMatchesFilter(int index) const {
  return index >= 0 && index < rowCount() && !rows_[index]->widget->isHidden();
}

void ParameterPanel::applyFilter() {
  const QString text = filter_->text().trimmed();
  for (auto& row : rows_) {
    row->widget->setHidden(!text.isEmpty() && !row->searchText.contains(text, Qt::CaseInsensitive));
  }
  for (auto& section : sections_) updateSection(*section);
  // Lay the rows out now and show the first match, rather than leaving the view where the old rows were.
  scroll_->widget()->layout()->activate();
  scroll_->verticalScrollBar()->setValue(0);
}

void ParameterPanel::updateSection(Section& section) {
  const bool filtering = !filter_->text().trimmed().isEmpty();
  const bool anyMatch =
      std::any_of(section.rows.begin(), section.rows.end(), [this](int i) { return rowMatchesFilter(i); });
  const bool open = filtering ? section.filterOpen : section.expanded;
  section.header->setHidden(!anyMatch);
  section.body->setHidden(!anyMatch || !open);
  section.header->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
  const QSignalBlocker block(section.header);
  section.header->setChecked(open);
}

}  // namespace kerf
