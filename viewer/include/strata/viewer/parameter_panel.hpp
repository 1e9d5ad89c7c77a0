#pragma once
#include <map>
#include <string>
#include <utility>

#include <strata/host/engine.hpp>
#include <strata/viewer/parameter_controls.hpp>

namespace strata::viewer {

// The viewer's panel of the scene's settings and every node's parameters (issue 9), drawn with Dear ImGui
// from parameterControls(),
// so each parameter is a control with its range, units and documentation: a slider for a bounded number, a
// field for an unbounded one, a checkbox, a list of choices, a text field. A live parameter changes as the
// control moves; any other when the control is let go, since it loads the pipeline again. A refused value
// is shown under the panel. Lists are shown, not edited (--set or the file change them). Call draw()
// between PanelOverlay::begin() and end().
class ParameterPanel {
 public:
  void draw(Engine& engine);
  // Shows `problem` under the panel until the next change succeeds (a pipeline file that no longer loads).
  void report(std::string problem) { refusal_ = std::move(problem); }
  // What the panel shows under it: the last refusal or report, or "".
  const std::string& reported() const { return refusal_; }

 private:
  void drawControl(Engine& engine, const ParameterControl& control);
  void change(Engine& engine, const ParameterControl& control, const ParameterValue& value, bool committed);

  std::map<std::string, std::string> editedText_;  // String and Path fields being typed in, by node.parameter
  std::string refusal_;                            // the last refused change's message, or a report
};

}  // namespace strata::viewer
