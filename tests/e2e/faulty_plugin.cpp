// composite.faulty: offers its input layer unchanged, and fails on purpose in the phase its `fails`
// parameter names, with a std::exception or (throws: other) with something that is none. Only the
// end-to-end fault tests load it: a third-party plugin may fail anywhere, and Strata must say which node
// failed and how, never crash.
#include <memory>
#include <stdexcept>
#include <string>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/plugin.hpp>

namespace strata::e2e {
namespace {

class Faulty : public Node {
 public:
  explicit Faulty(const NodeSetup& setup)
      : input_(setup.input("layer")),
        fails_(setup.parameters.string("fails")),
        other_(setup.parameters.string("throws") == "other") {
    failIn("create");
  }

  void open() override { failIn("open"); }
  void createResources(GpuContext&) override { failIn("resources"); }
  void prepare(const FrameState&) override { failIn("prepare"); }
  void render(const FrameState&) override { failIn("render"); }
  Layer* layer() override { return input_->layer(); }

 private:
  void failIn(const std::string& phase) const {
    if (phase != fails_) return;
    if (other_) throw 42;
    throw std::runtime_error("composite.faulty fails in " + phase + " as asked");
  }

  Node* input_;
  std::string fails_;
  bool other_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "composite.faulty";
  type.category = NodeCategory::Compositor;
  type.summary = "Offers its input layer, and fails on purpose (for the end-to-end fault tests)";
  type.inputs = {{.name = "layer", .type = PortType::Layer, .doc = "the layer to offer"}};
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "fails",
       .type = ParameterType::Choice,
       .defaultValue = std::string("render"),
       .doc = "the phase that fails",
       .choices = {"create", "open", "resources", "prepare", "render"}},
      {.name = "throws",
       .type = ParameterType::Choice,
       .defaultValue = std::string("exception"),
       .doc = "what it throws: a std::exception, or an int",
       .choices = {"exception", "other"}},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<Faulty>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::e2e

STRATA_PLUGIN("e2e-faulty", "0.1.0", strata::e2e::registerTypes)
