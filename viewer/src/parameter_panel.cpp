#include <strata/viewer/parameter_panel.hpp>

#include <algorithm>
#include <cstdint>

#include <imgui.h>

#include <strata/error.hpp>

namespace strata::viewer {
namespace {

// A slider spans a range a hand can sweep; wider ones (metres up to 1e7, say) are typed or dragged.
constexpr double kWidestSlider = 1.0e4;

bool sliderFits(const ParameterDeclaration& parameter) {
  return parameter.minimum && parameter.maximum && *parameter.maximum - *parameter.minimum <= kWidestSlider;
}

std::string labelOf(const ParameterDeclaration& parameter) {
  return parameter.units.empty() ? parameter.name : parameter.name + " (" + parameter.units + ")";
}

// Number controls: a slider where the range fits one, else a field; whether the value was changed.
template <class T>
bool numberControl(const ParameterDeclaration& parameter, ImGuiDataType type, T& value) {
  const std::string label = labelOf(parameter);
  if (!sliderFits(parameter)) return ImGui::InputScalar(label.c_str(), type, &value);
  const T least = T(*parameter.minimum), most = T(*parameter.maximum);
  return ImGui::SliderScalar(label.c_str(), type, &value, &least, &most);
}

bool choiceControl(const ParameterDeclaration& parameter, std::string& value) {
  bool changed = false;
  if (ImGui::BeginCombo(labelOf(parameter).c_str(), value.c_str())) {
    for (const std::string& choice : parameter.choices)
      if (ImGui::Selectable(choice.c_str(), choice == value)) changed = choice != value, value = choice;
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

void ParameterPanel::draw(Engine& engine) {
  // Out of the way at first, folded at the top left: the frame is what a viewer opens to see.
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  ImGui::Begin("Parameters");
  std::string node;
  bool open = false;
  for (const ParameterControl& control : parameterControls(engine)) {
    if (control.node != node) {
      node = control.node;
      open = ImGui::CollapsingHeader((node + "  " + control.type).c_str());
    }
    if (!open) continue;
    ImGui::PushID((node + "." + control.declaration->name).c_str());
    drawControl(engine, control);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", control.declaration->doc.c_str());
    ImGui::PopID();
  }
  if (!refusal_.empty()) ImGui::TextWrapped("%s", refusal_.c_str());
  ImGui::End();
}

void ParameterPanel::drawControl(Engine& engine, const ParameterControl& control) {
  const ParameterDeclaration& parameter = *control.declaration;
  ParameterValue value = control.value;
  bool changed = false;
  if (auto* real = std::get_if<double>(&value))
    changed = numberControl(parameter, ImGuiDataType_Double, *real);
  else if (auto* whole = std::get_if<std::int64_t>(&value))
    changed = numberControl(parameter, ImGuiDataType_S64, *whole);
  else if (auto* flag = std::get_if<bool>(&value))
    changed = ImGui::Checkbox(labelOf(parameter).c_str(), flag);
  else if (parameter.type == ParameterType::Choice)
    changed = choiceControl(parameter, std::get<std::string>(value));
  else if (auto* text = std::get_if<std::string>(&value)) {
    std::string& edited = editedText_.try_emplace(control.node + "." + parameter.name, *text).first->second;
    edited.resize(std::max<std::size_t>(edited.size(), 256));
    ImGui::InputText(labelOf(parameter).c_str(), edited.data(), edited.size());
    *text = edited.c_str();
    changed = *text != std::get<std::string>(control.value);
  } else {
    ImGui::LabelText(labelOf(parameter).c_str(), "%s", formatValue(value).c_str());
  }
  const bool committed = ImGui::IsItemDeactivatedAfterEdit() || (changed && !ImGui::IsItemActive());
  if (changed || committed) change(engine, control, value, committed);
}

// Live values follow the control; others wait until it is let go, each costing a load of the pipeline.
void ParameterPanel::change(Engine& engine, const ParameterControl& control, const ParameterValue& value,
                            bool committed) {
  if (!control.declaration->live && !committed) return;
  if (value == control.value) return;
  try {
    apply(engine, control, value);
    refusal_.clear();
    editedText_.clear();
  } catch (const Error& error) {
    refusal_ = error.what();
  }
}

}  // namespace strata::viewer
