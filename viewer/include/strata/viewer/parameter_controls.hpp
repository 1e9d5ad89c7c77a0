#pragma once
#include <string>
#include <vector>

#include <strata/host/engine.hpp>
#include <strata/plugin/parameter.hpp>

namespace strata::viewer {

// One parameter of one node, or of one of the scene's sections (body, camera, cache, colour), as a control
// of the viewer's panel (issue 9): what its declaration says (type, range, units, documentation, whether it
// is live) and its value now. The panel is generated from these, so every parameter is a control with
// nothing written per node type or section.
struct ParameterControl {
  std::string node;                         // the node's id, or the scene section's name
  std::string type;                         // the node's type, composite.relief, or "scene"
  std::string path;                         // what an override names it by before its own name: nodes.ID, camera
  const ParameterDeclaration* declaration;  // owned by the engine's plugin registry, or the scene's declarations
  ParameterValue value;
};

// The controls of the scene's sections, then of every parameter of every node of the engine's loaded
// pipeline, in the pipeline's order. The camera's are the engine's camera now, which the viewer moves.
std::vector<ParameterControl> parameterControls(Engine& engine);

// The --set override that gives `control` the value `value`: "nodes.ID.NAME=VALUE" or "SECTION.NAME=VALUE",
// VALUE as YAML (text quoted, lists bracketed, dates as ISO 8601).
std::string overrideOf(const ParameterControl& control, const ParameterValue& value);

// Gives the control its new value and returns whether it was live: the camera's move the engine's camera for
// the next frame; others go through Engine::set (live node parameters in the next frame, others by loading
// the pipeline again, keeping the camera). Throws strata::Error as Engine::set does, with nothing changed.
bool apply(Engine& engine, const ParameterControl& control, const ParameterValue& value);

}  // namespace strata::viewer
