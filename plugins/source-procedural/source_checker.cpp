#include "source_checker.hpp"

#include <memory>

#include <strata/node.hpp>

#include "checker_layer.hpp"

namespace strata::procedural {
namespace {

class CheckerSource : public Node {
 public:
  explicit CheckerSource(const NodeSetup& setup)
      : layer_(setup.id, glm::radians(glm::dvec2(setup.parameters.real("lon"), setup.parameters.real("lat"))),
               setup.parameters.real("cell"), setup.body->radius) {}

  void prepare(const FrameState& frame) override { layer_.follow(frame.view); }
  Layer* layer() override { return &layer_; }

 private:
  CheckerLayer layer_;
};

}  // namespace

NodeTypeDeclaration checkerDeclaration() {
  NodeTypeDeclaration type;
  type.type = "source.checker";
  type.category = NodeCategory::Source;
  type.summary =
      "A checkerboard of square cells laid on the ground around a point: how precisely the surface is placed";
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "lon",
       .type = ParameterType::Real,
       .defaultValue = 0.0,
       .minimum = -180.0,
       .maximum = 180.0,
       .units = "deg",
       .doc = "longitude of a corner of the board's cells"},
      {.name = "lat",
       .type = ParameterType::Real,
       .defaultValue = 0.0,
       .minimum = -89.0,
       .maximum = 89.0,
       .units = "deg",
       .doc = "latitude of that corner; cells are square along its parallel"},
      {.name = "cell",
       .type = ParameterType::Real,
       .defaultValue = 0.01,
       .minimum = 1e-4,
       .maximum = 1e7,
       .units = "m",
       .doc = "side of a cell (1 cm: issue 4's test of precision from 2 m up)"},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<CheckerSource>(setup); };
  return type;
}

}  // namespace strata::procedural
