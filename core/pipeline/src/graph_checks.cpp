#include "graph_checks.hpp"

#include <algorithm>
#include <map>

#include "pipeline/graph_order.hpp"
#include "pipeline/suggestions.hpp"

namespace strata::loader {
namespace {

using NodeIndex = std::map<std::string, std::size_t>;

std::string offered(const NodeTypeDeclaration& declaration) {
  return declaration.output ? std::string("a ") + toString(*declaration.output) : "nothing (it is an output)";
}

std::size_t targetOf(const ParsedNode& node, const InputReference& reference, const NodeIndex& index,
                     const SourceMap& source) {
  const std::string& id = node.description.id;
  if (reference.target == id)
    throw source.error(reference.value, id, "node '" + id + "' takes its own result as input '" + reference.port + "'",
                       "name another node on '" + reference.port + "'");
  auto found = index.find(reference.target);
  if (found != index.end()) return found->second;
  std::vector<std::string> ids;
  for (const auto& [name, position] : index) ids.push_back(name);
  throw source.error(reference.value, id,
                     "input '" + reference.port + "' refers to '" + reference.target + "', which is not a node" +
                         didYouMean(reference.target, ids),
                     "name one of the nodes: " + quotedList(ids));
}

void requireOffers(const ParsedNode& node, const InputReference& reference, const ParsedNode& target,
                   const SourceMap& source) {
  const PortType wanted = node.declaration->findInput(reference.port)->type;
  if (target.declaration->output == wanted) return;
  throw source.error(reference.value, node.description.id,
                     "input '" + reference.port + "' takes a " + toString(wanted) + ", but node '" + reference.target +
                         "' (" + target.description.type + ") offers " + offered(*target.declaration),
                     "name a node that offers a " + std::string(toString(wanted)) + " on '" + reference.port + "'");
}

InputGraph checkReferences(const std::vector<ParsedNode>& nodes, const SourceMap& source) {
  NodeIndex index;
  for (std::size_t i = 0; i < nodes.size(); ++i) index.emplace(nodes[i].description.id, i);
  InputGraph inputsOf(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (const auto& reference : nodes[i].references) {
      const std::size_t target = targetOf(nodes[i], reference, index, source);
      requireOffers(nodes[i], reference, nodes[target], source);
      inputsOf[i].push_back(target);
    }
  }
  return inputsOf;
}

void requireOneOutput(const std::vector<ParsedNode>& nodes, const YAML::Node& nodesMap, const SourceMap& source) {
  std::vector<const ParsedNode*> outputs;
  std::vector<std::string> ids;
  for (const auto& node : nodes) {
    if (node.declaration->category != NodeCategory::Output) continue;
    outputs.push_back(&node);
    ids.push_back(node.description.id);
  }
  if (outputs.empty())
    throw source.error(nodesMap, {}, "the pipeline has no output node",
                       "add one node of an output type, e.g. `frame: {type: output.image, ...}`; `strata plugins` "
                       "lists the types");
  if (outputs.size() > 1)
    throw source.entryError(outputs[1]->key, outputs[1]->value, outputs[1]->description.id,
                            "the pipeline has " + std::to_string(outputs.size()) + " output nodes (" + quotedList(ids) +
                                "); it must have exactly one",
                            "keep one output node; render other outputs with a pipeline of their own");
}

Error cycleError(const std::vector<ParsedNode>& nodes, const std::vector<std::size_t>& cycle, const SourceMap& source) {
  std::string path;
  for (std::size_t node : cycle) path += nodes[node].description.id + " -> ";
  path += nodes[cycle.front()].description.id;
  // Located at the first edge of the cycle: where its first node names the second.
  const ParsedNode& first = nodes[cycle.front()];
  const std::string& second = nodes[cycle[cycle.size() > 1 ? 1 : 0]].description.id;
  const auto edge = std::find_if(first.references.begin(), first.references.end(),
                                 [&](const InputReference& reference) { return reference.target == second; });
  return source.error(edge->value, first.description.id,
                      "the nodes' inputs form a cycle: " + path + " (each takes input from the next)",
                      "remove one of these inputs: every node must come after the nodes it takes input from");
}

}  // namespace

std::vector<NodeDescription> connectNodes(std::vector<ParsedNode> nodes, const YAML::Node& nodesMap,
                                          const SourceMap& source) {
  const InputGraph inputsOf = checkReferences(nodes, source);
  requireOneOutput(nodes, nodesMap, source);
  const DependencyOrder order = orderByDependencies(inputsOf);
  if (!order.cycle.empty()) throw cycleError(nodes, order.cycle, source);
  std::vector<NodeDescription> ordered;
  for (std::size_t node : order.order) ordered.push_back(std::move(nodes[node].description));
  return ordered;
}

}  // namespace strata::loader
