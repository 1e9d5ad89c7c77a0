#include "explorer_panel.hpp"

#include <stdexcept>

#include <imgui.h>

#include <strata/error.hpp>

namespace explorer {
namespace {

// The pipeline's output node: the one of category Output (output.image takes the `surface` list).
const strata::NodeDescription& outputNode(strata::Engine& engine) {
  for (const strata::NodeDescription& node : engine.pipeline().nodes) {
    const strata::NodeTypeDeclaration* type = engine.plugins().find(node.type);
    if (type && type->category == strata::NodeCategory::Output && node.inputs.contains("surface")) return node;
  }
  throw std::runtime_error(engine.pipeline().name + ": no output node with a `surface` list to explore");
}

}  // namespace

ExplorerPanel::ExplorerPanel(strata::Engine& engine) : engine_(engine), pipelineDate_(engine.pipeline().date) {
  const strata::NodeDescription& output = outputNode(engine);
  output_ = output.id;
  for (const std::string& id : output.inputs.at("surface")) layers_.push_back({id, true});
}

void ExplorerPanel::draw() {
  // At the top left, sized to what it holds; the frame around it stays the planet's.
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
  ImGui::Begin("Mars explorer", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  drawLayers();
  drawDate();
  drawCamera();
  if (!problem_.empty()) ImGui::TextWrapped("%s", problem_.c_str());
  ImGui::End();
}

// One checkbox a layer; the last one shown cannot be unticked, as an output needs a surface.
void ExplorerPanel::drawLayers() {
  ImGui::TextUnformatted("Layers");
  int shown = 0;
  for (const LayerEntry& layer : layers_) shown += layer.shown ? 1 : 0;
  for (LayerEntry& layer : layers_) {
    ImGui::BeginDisabled(layer.shown && shown == 1);
    if (ImGui::Checkbox(layer.id.c_str(), &layer.shown)) applyLayers();
    ImGui::EndDisabled();
  }
}

// Days either side of the pipeline's date; the engine shows time series at the date, with no reload.
void ExplorerPanel::drawDate() {
  if (!pipelineDate_ || !engine_.date()) return;
  float offset = static_cast<float>(*engine_.date() - *pipelineDate_);
  const std::string label = strata::formatIsoDate(*engine_.date());
  if (ImGui::SliderFloat("Date", &offset, -365.0f, 365.0f, label.c_str()))
    engine_.date() = *pipelineDate_ + static_cast<double>(offset);
}

void ExplorerPanel::drawCamera() {
  strata::Camera& camera = engine_.camera();
  float lon = static_cast<float>(camera.lon), lat = static_cast<float>(camera.lat);
  float altitude = static_cast<float>(camera.altitude / 1000.0);
  if (ImGui::SliderFloat("Longitude", &lon, -180.0f, 180.0f, "%.1f deg")) camera.lon = lon;
  if (ImGui::SliderFloat("Latitude", &lat, -90.0f, 90.0f, "%.1f deg")) camera.lat = lat;
  // 1 km to 50,000 km, logarithmic: from a crater's rim to the whole disc of any planet
  if (ImGui::SliderFloat("Altitude", &altitude, 1.0f, 5.0e4f, "%.0f km", ImGuiSliderFlags_Logarithmic))
    camera.altitude = static_cast<double>(altitude) * 1000.0;
}

void ExplorerPanel::showLayer(const std::string& id, bool shown) {
  for (LayerEntry& layer : layers_)
    if (layer.id == id) {
      layer.shown = shown;
      return applyLayers();
    }
  throw std::invalid_argument("no layer '" + id + "' in the output's surface list");
}

void ExplorerPanel::setDate(const std::string& isoDate) {
  const std::optional<strata::DayNumber> date = strata::parseIsoDate(isoDate);
  if (!date) throw std::invalid_argument("'" + isoDate + "' is no date: write YYYY-MM-DD");
  engine_.date() = *date;
}

// The ticked layers as the output's new surface list: a reload (the list is not a live parameter) that
// keeps the camera and the date.
void ExplorerPanel::applyLayers() {
  std::string list;
  for (const LayerEntry& layer : layers_)
    if (layer.shown) list += (list.empty() ? "" : ", ") + layer.id;
  try {
    engine_.set("nodes." + output_ + ".surface=[" + list + "]");
    problem_.clear();
  } catch (const strata::Error& error) {
    problem_ = error.what();
  }
}

}  // namespace explorer
