#include <strata/error.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/node.hpp>

namespace strata {

std::vector<const Layer*> layersOfOneKind(const std::vector<Node*>& nodes, const std::string& what,
                                          const SourceLocation& where) {
  std::vector<const Layer*> layers;
  for (Node* node : nodes) layers.push_back(node->layer());
  for (const Layer* layer : layers)
    if (layer->kind() != layers.front()->kind())
      throw Error(where,
                  "the " + what + " are of different kinds (" + toString(layers.front()->kind()) + " and " +
                      toString(layer->kind()) + "), which cannot be blended",
                  "give " + what + " of one kind: heights with heights, colours with colours");
  return layers;
}

}  // namespace strata
