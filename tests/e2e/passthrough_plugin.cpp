// composite.passthrough: offers its input layer unchanged. Only the end-to-end tests load it (from their
// build directory): they need a node type that both takes and offers a layer to write a pipeline whose
// inputs form a cycle, and no plugin shipped with Strata has one yet.
#include <memory>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/plugin.hpp>

namespace strata::e2e {
namespace {

class Passthrough : public Node {
 public:
  explicit Passthrough(const NodeSetup& setup) : input_(setup.input("layer")) {}

  Layer* layer() override { return input_->layer(); }

 private:
  Node* input_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "composite.passthrough";
  type.category = NodeCategory::Compositor;
  type.summary = "Offers its input layer unchanged (for the end-to-end tests)";
  type.inputs = {{.name = "layer", .type = PortType::Layer, .doc = "the layer to offer"}};
  type.output = PortType::Layer;
  type.create = [](const NodeSetup& setup) { return std::make_unique<Passthrough>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::e2e

STRATA_PLUGIN("e2e-passthrough", "0.1.0", strata::e2e::registerTypes)
