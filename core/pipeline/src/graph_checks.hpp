#pragma once
#include <vector>

#include <yaml-cpp/yaml.h>

#include <strata/host/pipeline.hpp>

#include "node_parsing.hpp"
#include "pipeline/source_map.hpp"

namespace strata::loader {

// Checks how the nodes connect, then orders them. Checked in this order, each error located at the
// reference or node concerned:
//  - every referenced id is a node (did-you-mean among the ids), and not the referring node itself;
//  - a Geometry port refers to a node that offers a geometry, a Layer port to one that offers a layer;
//    output nodes offer nothing (layer kinds are checked later, by the engine);
//  - exactly one node is of category Output;
//  - the references form no cycle (the message lists it: a -> b -> a, "a takes input from b").
// Returns the descriptions in dependency order (graph_order.hpp); `nodesMap` locates "no output node".
std::vector<NodeDescription> connectNodes(std::vector<ParsedNode> nodes, const YAML::Node& nodesMap,
                                          const SourceMap& source);

}  // namespace strata::loader
