#include "source_checker.hpp"

#include <memory>

#include <strata/plugin/node.hpp>
#include <strata/plugin/parameter_bindings.hpp>

#include "checker_layer.hpp"

namespace strata::procedural {
namespace {

// The node's settings as a pipeline writes them.
struct CheckerSettings {
  double lon = 0.0;
  double lat = 0.0;
  double cell = 0.01;  // 1 cm: issue 4's test of precision from 2 m up
};

const ParameterBindings<CheckerSettings>& checkerParameters() {
  using S = CheckerSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::lon, {.name = "lon",
                         .minimum = -180.0,
                         .maximum = 180.0,
                         .units = "deg",
                         .doc = "longitude of a corner of the board's cells"})
          .add(&S::lat, {.name = "lat",
                         .minimum = -89.0,
                         .maximum = 89.0,
                         .units = "deg",
                         .doc = "latitude of that corner; cells are square along its parallel"})
          .add(&S::cell, {.name = "cell",
                          .minimum = 1e-4,
                          .maximum = 1e7,
                          .units = "m",
                          .doc = "side of a cell (1 cm: issue 4's test of precision from 2 m up)"});
  return bindings;
}

class CheckerSource : public Node {
 public:
  explicit CheckerSource(const NodeSetup& setup) : CheckerSource(setup, checkerParameters().read(setup.parameters)) {}

  void prepare(const FrameState& frame) override { layer_.follow(frame.view); }
  Layer* layer() override { return &layer_; }

 private:
  CheckerSource(const NodeSetup& setup, const CheckerSettings& settings)
      : layer_(setup.id, glm::radians(glm::dvec2(settings.lon, settings.lat)), settings.cell, setup.body->radius) {}

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
  type.parameters = checkerParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<CheckerSource>(setup); };
  return type;
}

}  // namespace strata::procedural
