#pragma once
#include <string>
#include <vector>

#include <strata/engine.hpp>
#include <strata/parameter.hpp>

namespace strata::viewer {

// One parameter of one node as a control of the viewer's panel (issue 9): what its declaration says (type,
// range, units, documentation, whether it is live) and its value now. The panel is generated from these,
// so every node's parameters are controls with nothing written per node type.
struct ParameterControl {
  std::string node;                         // the node's id
  std::string type;                         // the node's type, composite.relief
  const ParameterDeclaration* declaration;  // owned by the engine's plugin registry
  ParameterValue value;
};

// The controls of every parameter of every node of the engine's loaded pipeline, in the pipeline's order.
std::vector<ParameterControl> parameterControls(Engine& engine);

// The --set override that gives `control` the value `value`: "nodes.ID.NAME=VALUE", VALUE as YAML (text
// quoted, lists bracketed).
std::string overrideOf(const ParameterControl& control, const ParameterValue& value);

// Gives the control its new value through the engine (Engine::set: live parameters in the next frame,
// others by loading the pipeline again, keeping the camera) and returns whether it was live. Throws
// strata::Error as Engine::set does, with nothing changed.
bool apply(Engine& engine, const ParameterControl& control, const ParameterValue& value);

}  // namespace strata::viewer
