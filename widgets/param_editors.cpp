#include "param_editors.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>
#include <QToolButton>
#include <type_traits>

namespace sonarcarve::widgets {
namespace {

QString text(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString toolTip(const ParamSpec& spec) {
  QString help = text(spec.help);
  help[0] = help[0].toUpper();
  return help + " (" + text(describeAccepted(spec)) + ")";
}

// A spin box: QDoubleSpinBox for a Number, shown in the schema's units times the panel's
// factor; QSpinBox for an Integer.
template <typename SpinBox>
class SpinEditor : public ParamEditor {
  static constexpr bool kReal = std::is_same_v<SpinBox, QDoubleSpinBox>;
  using Shown = std::conditional_t<kReal, double, int>;

 public:
  SpinEditor(const ParamSpec& spec, QWidget* parent)
      : ParamEditor(spec), box_(new SpinBox(parent)) {
    const ParamGui& g = spec.gui;
    box_->setRange(static_cast<Shown>(g.min), static_cast<Shown>(g.max));
    box_->setSingleStep(static_cast<Shown>(g.step));
    if constexpr (kReal) {
      box_->setDecimals(g.decimals);
    }
    box_->setSuffix(text(g.suffix));
    box_->setSpecialValueText(text(g.min_text));
    box_->setKeyboardTracking(false);
  }
  QWidget* widget() const override { return box_; }
  void show(const ParamValue& value) override {
    if constexpr (kReal) {
      box_->setValue(spec().toShown(std::get<double>(value)) * spec().gui.factor);
    } else {
      box_->setValue(static_cast<int>(std::get<long long>(value)));
    }
  }
  std::optional<ParamValue> value() const override {
    if constexpr (kReal) {
      return spec().fromShown(box_->value() / spec().gui.factor);
    } else {
      return static_cast<long long>(box_->value());
    }
  }
  void onChange(std::function<void()> changed) override {
    QObject::connect(box_, &SpinBox::valueChanged, box_, [changed] { changed(); });
  }

 private:
  SpinBox* box_;
};

class BoolEditor : public ParamEditor {
 public:
  BoolEditor(const ParamSpec& spec, QWidget* parent)
      : ParamEditor(spec), box_(new QCheckBox(text(spec.gui.label), parent)) {}
  QWidget* widget() const override { return box_; }
  void show(const ParamValue& value) override { box_->setChecked(std::get<bool>(value)); }
  std::optional<ParamValue> value() const override { return box_->isChecked(); }
  void onChange(std::function<void()> changed) override {
    QObject::connect(box_, &QCheckBox::toggled, box_, [changed] { changed(); });
  }

 private:
  QCheckBox* box_;
};

class EnumEditor : public ParamEditor {
 public:
  EnumEditor(const ParamSpec& spec, QWidget* parent)
      : ParamEditor(spec), box_(new QComboBox(parent)) {
    for (const std::string_view choice : spec.access.choices) {
      box_->addItem(text(choice));
    }
  }
  QWidget* widget() const override { return box_; }
  void show(const ParamValue& value) override {
    box_->setCurrentText(QString::fromStdString(std::get<std::string>(value)));
  }
  std::optional<ParamValue> value() const override { return box_->currentText().toStdString(); }
  void onChange(std::function<void()> changed) override {
    QObject::connect(box_, &QComboBox::currentIndexChanged, box_, [changed] { changed(); });
  }

 private:
  QComboBox* box_;
};

// A line of text: a file path with a browse button, or the six numbers of a box.
class LineEditor : public ParamEditor {
 public:
  LineEditor(const ParamSpec& spec, QWidget* parent)
      : ParamEditor(spec), row_(new QWidget(parent)), line_(new QLineEdit) {
    auto* layout = new QHBoxLayout(row_);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(line_);
    line_->setPlaceholderText(text(spec.gui.min_text));
    if (spec.type() == ParamType::Path) {
      browse_ = new QToolButton;
      browse_->setText("…");
      layout->addWidget(browse_);
    }
  }
  QWidget* widget() const override { return row_; }
  void show(const ParamValue& value) override {
    line_->setText(QString::fromStdString(formatParam(spec(), value)));
  }
  std::optional<ParamValue> value() const override {
    const std::string typed = line_->text().trimmed().toStdString();
    if (spec().type() == ParamType::Box && typed.empty()) {
      return OptionalBox();
    }
    const ParsedValue parsed = parseParam(spec(), typed);
    if (!parsed.problem.empty()) {
      return std::nullopt;
    }
    return parsed.value;
  }
  void onChange(std::function<void()> changed) override {
    QObject::connect(line_, &QLineEdit::editingFinished, line_, [changed] { changed(); });
    if (browse_ != nullptr) {
      QObject::connect(browse_, &QToolButton::clicked, line_, [this, changed] {
        const QString file = QFileDialog::getOpenFileName(
            row_, text(spec().gui.label), QString(), QObject::tr("YAML (*.yaml *.yml);;All (*)"));
        if (!file.isEmpty()) {
          line_->setText(file);
          changed();
        }
      });
    }
  }

 private:
  QWidget* row_;
  QLineEdit* line_;
  QToolButton* browse_ = nullptr;
};

}  // namespace

std::unique_ptr<ParamEditor> makeParamEditor(const ParamSpec& spec, QWidget* parent) {
  std::unique_ptr<ParamEditor> editor;
  switch (spec.type()) {
    case ParamType::Number:
      editor = std::make_unique<SpinEditor<QDoubleSpinBox>>(spec, parent);
      break;
    case ParamType::Integer:
      editor = std::make_unique<SpinEditor<QSpinBox>>(spec, parent);
      break;
    case ParamType::Bool:
      editor = std::make_unique<BoolEditor>(spec, parent);
      break;
    case ParamType::Enum:
      editor = std::make_unique<EnumEditor>(spec, parent);
      break;
    case ParamType::Path:
    case ParamType::Box:
      editor = std::make_unique<LineEditor>(spec, parent);
      break;
  }
  editor->widget()->setToolTip(toolTip(spec));
  return editor;
}

}  // namespace sonarcarve::widgets
