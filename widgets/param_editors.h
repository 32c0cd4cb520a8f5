// The editor of one parameter-schema entry in the ParamsPanel, chosen by the entry's type:
// a spin box for numbers, a combo box for enums, a check box, a path with a browse button, a
// line of six numbers for a box. Editors show and read values in the struct's own units; the
// schema's conversions (degrees, the panel's factor) happen inside. GUI thread only.
#pragma once

#include <QWidget>
#include <functional>
#include <memory>
#include <optional>

#include "pipeline/param_schema.h"

namespace sonarcarve::widgets {

class ParamEditor {
 public:
  explicit ParamEditor(const ParamSpec& spec) : spec_(spec) {}
  virtual ~ParamEditor() = default;
  ParamEditor(const ParamEditor&) = delete;
  ParamEditor& operator=(const ParamEditor&) = delete;

  const ParamSpec& spec() const { return spec_; }
  /// The widget placed in the panel's form (owned by the panel once placed).
  virtual QWidget* widget() const = 0;
  virtual void show(const ParamValue& value) = 0;
  /// The value shown, or nothing while the text typed is not valid.
  virtual std::optional<ParamValue> value() const = 0;
  /// `changed` runs whenever the user changes the value.
  virtual void onChange(std::function<void()> changed) = 0;

 private:
  const ParamSpec& spec_;
};

/// The editor for `spec`'s type; `parent` owns its widget.
std::unique_ptr<ParamEditor> makeParamEditor(const ParamSpec& spec, QWidget* parent);

}  // namespace sonarcarve::widgets
