#pragma once
#include <cstddef>
#include <strata/export.hpp>
#include <vector>

// Ordering a pipeline's nodes so that every node comes after its inputs.
// Not part of the SDK: exported from libstrata_core for Strata's own tests and tools.
STRATA_EXPORTS_BEGIN
namespace strata::loader {

// Nodes are numbered 0..n-1 in the order the file lists them; inputsOf[i] holds the nodes node i takes
// input from (a node may appear more than once).
using InputGraph = std::vector<std::vector<std::size_t>>;

struct DependencyOrder {
  std::vector<std::size_t> order;  // every node after its inputs; only the orderable ones when cyclic
  // Empty when the graph is acyclic; otherwise one cycle a, b, c: a takes input from b, b from c, c from
  // a. It starts at its earliest node in file order, so the same file always reports the same cycle.
  std::vector<std::size_t> cycle;
};

// Kahn's algorithm, made stable: of the nodes whose inputs are all placed, the one earliest in the file
// goes next. A file already in dependency order keeps its order, and the order never depends on
// container internals.
DependencyOrder orderByDependencies(const InputGraph& inputsOf);

}  // namespace strata::loader
STRATA_EXPORTS_END
