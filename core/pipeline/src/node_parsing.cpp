#include "node_parsing.hpp"

#include <algorithm>

#include "pipeline/parameter_parsing.hpp"
#include "pipeline/suggestions.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"

namespace strata::loader {
namespace {

bool isIdentifier(const std::string& id) {
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  auto inner = [&](char c) { return letter(c) || (c >= '0' && c <= '9') || c == '_' || c == '-'; };
  return !id.empty() && letter(id[0]) && std::all_of(id.begin(), id.end(), inner);
}

std::string nodeName(const ParsedNode& node) {
  return "node '" + node.description.id + "' (" + node.description.type + ")";
}

// "(geometry): the surface to shade", for a message about a missing input or parameter.
std::string typeAndDoc(const std::string& type, const std::string& doc) {
  return "(" + type + ")" + (doc.empty() ? "" : ": " + doc);
}

std::string readId(const YAML::Node& key, const YAML::Node& value, const SourceMap& source) {
  const std::string id = keyText(key, value, source);
  if (!isIdentifier(id))
    throw source.entryError(key, value, {}, "node id '" + id + "' is not a valid identifier",
                            "start the id with a letter and use only letters, digits, '_' and '-'");
  return id;
}

void requireNodeMap(const ParsedNode& node, const SourceMap& source) {
  const std::string& id = node.description.id;
  if (!node.value.IsMap())
    throw source.entryError(node.key, node.value, id,
                            "node '" + id + "' must be a map with a 'type', got " + describe(node.value),
                            "write it as `" + id + ": {type: source.gdal, ...}`");
}

std::vector<std::string> registeredTypes(const PluginRegistry& registry) {
  std::vector<std::string> names;
  for (const auto* declaration : registry.types()) names.push_back(declaration->type);
  return names;
}

const NodeTypeDeclaration& declarationOf(const ParsedNode& node, const NodeContext& context) {
  const std::string& id = node.description.id;
  const YAML::Node typeValue = node.value["type"];
  if (!typeValue)
    throw context.source.entryError(node.key, node.value, id, "node '" + id + "' has no 'type'",
                                    "add `type:` with a node type; `strata plugins` lists them");
  const std::string type = readText(typeValue, {context.source, "'type' of node '" + id + "'", id});
  if (const auto* declaration = context.registry.find(type)) return *declaration;
  throw context.source.error(typeValue, id,
                             "unknown node type '" + type + "'" + didYouMean(type, registeredTypes(context.registry)),
                             "run `strata plugins` to see the node types available");
}

std::vector<std::string> namesOf(const auto& declarations) {
  std::vector<std::string> names;
  for (const auto& declaration : declarations) names.push_back(declaration.name);
  return names;
}

Error unknownKey(const ParsedNode& node, const YAML::Node& key, const YAML::Node& value, const std::string& name,
                 const SourceMap& source) {
  const NodeTypeDeclaration& declaration = *node.declaration;
  std::vector<std::string> known = namesOf(declaration.inputs);
  const std::vector<std::string> parameters = namesOf(declaration.parameters);
  known.insert(known.end(), parameters.begin(), parameters.end());
  const auto listed = [](const std::vector<std::string>& names, const std::string& what) {
    return names.empty() ? "no " + what : "the " + what + " " + quotedList(names);
  };
  return source.entryError(key, value, node.description.id,
                           nodeName(node) + " has no input or parameter '" + name + "'" + didYouMean(name, known),
                           declaration.type + " takes " + listed(namesOf(declaration.inputs), "inputs") + " and " +
                               listed(parameters, "parameters") + "; `strata plugins --describe " + declaration.type +
                               "` explains them");
}

// The YAML scalars that name the port's upstream nodes.
std::vector<YAML::Node> referenceValues(const PortDeclaration& port, const YAML::Node& value, const ParsedNode& node,
                                        const SourceMap& source) {
  if (value.IsSequence() && !port.list)
    throw source.error(value, node.description.id, "input '" + port.name + "' takes one node, got a list",
                       "give a single node id, e.g. `" + port.name + ": relief`");
  std::vector<YAML::Node> values;
  if (value.IsSequence()) {
    for (const auto& item : value) values.push_back(item);
  } else {
    values.push_back(value);
  }
  for (const auto& item : values)
    if (!item.IsScalar())
      throw source.error(item, node.description.id,
                         "input '" + port.name + "' expects a node id, got " + describe(item),
                         "write the id of the node it takes input from, e.g. `" + port.name + ": relief`");
  return values;
}

void readInput(const PortDeclaration& port, const YAML::Node& value, ParsedNode& node, const SourceMap& source) {
  std::vector<std::string> ids;
  std::vector<SourceLocation> locations;
  for (const auto& item : referenceValues(port, value, node, source)) {
    ids.push_back(item.Scalar());
    locations.push_back(source.at(item, node.description.id));
    node.references.push_back({port.name, item.Scalar(), item});
  }
  if (ids.empty()) return;  // an empty list connects nothing
  node.description.inputs[port.name] = std::move(ids);
  node.description.inputLocations[port.name] = std::move(locations);
}

void readEntries(ParsedNode& node, const NodeContext& context) {
  const std::string& id = node.description.id;
  for (const auto& entry : node.value) {
    const std::string name = keyText(entry.first, entry.second, context.source, id);
    if (name == "type") continue;
    if (const PortDeclaration* port = node.declaration->findInput(name)) {
      readInput(*port, entry.second, node, context.source);
    } else if (const ParameterDeclaration* parameter = node.declaration->findParameter(name)) {
      const ValueContext valueContext{context.source, "parameter '" + name + "'", id};
      node.description.parameters.set(name,
                                      parseParameter(entry.second, *parameter, valueContext, context.baseDirectory),
                                      context.source.at(entry.second, id));
    } else {
      throw unknownKey(node, entry.first, entry.second, name, context.source);
    }
  }
}

void requireInputs(const ParsedNode& node, const SourceMap& source) {
  for (const auto& port : node.declaration->inputs) {
    if (port.optional || node.description.inputs.count(port.name)) continue;
    throw source.entryError(node.key, node.value, node.description.id,
                            nodeName(node) + " is missing its input '" + port.name + "' " +
                                typeAndDoc(toString(port.type) + std::string(port.list ? " list" : ""), port.doc),
                            "add `" + port.name + ": ID`, naming a node that offers a " + toString(port.type));
  }
}

void fillDefaults(ParsedNode& node, const SourceMap& source) {
  for (const auto& parameter : node.declaration->parameters) {
    if (node.description.parameters.has(parameter.name) || (parameter.optional && !parameter.defaultValue)) continue;
    if (!parameter.defaultValue)
      throw source.entryError(node.key, node.value, node.description.id,
                              nodeName(node) + " is missing required parameter '" + parameter.name + "' " +
                                  typeAndDoc(toString(parameter.type), parameter.doc),
                              "add `" + parameter.name + ": VALUE` to the node");
    node.description.parameters.set(parameter.name, defaultValue(parameter), node.description.where);
  }
}

}  // namespace

ParsedNode parseNode(const YAML::Node& key, const YAML::Node& value, const NodeContext& context) {
  ParsedNode node{NodeDescription{}, nullptr, key, value, {}};
  node.description.id = readId(key, value, context.source);
  node.description.where = context.source.atEntry(key, value, node.description.id);
  requireNodeMap(node, context.source);
  requireUniqueKeys(value, context.source, "key", node.description.id);
  node.declaration = &declarationOf(node, context);
  node.description.type = node.declaration->type;
  readEntries(node, context);
  requireInputs(node, context.source);
  fillDefaults(node, context.source);
  return node;
}

}  // namespace strata::loader
