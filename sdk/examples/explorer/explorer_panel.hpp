#pragma once
#include <optional>
#include <string>
#include <vector>

#include <strata/date.hpp>
#include <strata/host/engine.hpp>

namespace explorer {

// The explorer's own controls, drawn with Dear ImGui over the engine's frame: the output's surface layers
// as a list to tick, a date slider a year either side of the pipeline's date (where it gives one), and the
// camera's longitude, latitude and altitude. Every change goes through the engine's public calls
// (Engine::set, Engine::date, Engine::camera), which is all a host needs.
class ExplorerPanel {
 public:
  // Reads the layer list from the pipeline's output node. Throws std::runtime_error when it has none.
  explicit ExplorerPanel(strata::Engine& engine);

  void draw();  // between the window's beginPanel() and endPanel()

  // What the controls do, for the command line as well. showLayer and setDate throw std::invalid_argument
  // for a layer or a date that is not there; a pipeline that refuses the change keeps its layers and says
  // why in the panel.
  void showLayer(const std::string& id, bool shown);
  void setDate(const std::string& isoDate);
  void setAltitude(double metres) { engine_.camera().altitude = metres; }

 private:
  struct LayerEntry {
    std::string id;
    bool shown = true;
  };

  void drawLayers();
  void drawDate();
  void drawCamera();
  void applyLayers();

  strata::Engine& engine_;
  std::string output_;              // the id of the node whose `surface` list the layers are
  std::vector<LayerEntry> layers_;  // in the pipeline's order, which is the order they compose in
  std::optional<strata::DayNumber> pipelineDate_;
  std::string problem_;  // the last change the engine refused, shown in the panel
};

}  // namespace explorer
