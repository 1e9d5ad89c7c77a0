#include "pipeline/graph_order.hpp"

#include <algorithm>
#include <set>

namespace strata::loader {
namespace {

InputGraph usersOf(const InputGraph& inputsOf) {
  InputGraph users(inputsOf.size());
  for (std::size_t node = 0; node < inputsOf.size(); ++node)
    for (std::size_t input : inputsOf[node]) users[input].push_back(node);
  return users;
}

// Every node left unplaced by Kahn's algorithm waits on another unplaced node, so walking from one
// unplaced node to an unplaced input must come back to a node already visited: that loop is a cycle.
std::vector<std::size_t> findCycle(const InputGraph& inputsOf, const std::vector<bool>& placed) {
  const auto start = static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
  std::vector<std::size_t> path;
  std::vector<bool> visited(inputsOf.size(), false);
  for (std::size_t node = start; !visited[node];) {
    visited[node] = true;
    path.push_back(node);
    node =
        *std::find_if(inputsOf[node].begin(), inputsOf[node].end(), [&](std::size_t input) { return !placed[input]; });
    if (visited[node]) path.erase(path.begin(), std::find(path.begin(), path.end(), node));
  }
  std::rotate(path.begin(), std::min_element(path.begin(), path.end()), path.end());
  return path;
}

}  // namespace

DependencyOrder orderByDependencies(const InputGraph& inputsOf) {
  const InputGraph users = usersOf(inputsOf);
  std::vector<std::size_t> waitingOn(inputsOf.size());
  std::set<std::size_t> ready;  // ordered, so the earliest node in the file comes first
  for (std::size_t node = 0; node < inputsOf.size(); ++node) {
    waitingOn[node] = inputsOf[node].size();
    if (waitingOn[node] == 0) ready.insert(node);
  }
  DependencyOrder result;
  std::vector<bool> placed(inputsOf.size(), false);
  while (!ready.empty()) {
    const std::size_t node = *ready.begin();
    ready.erase(ready.begin());
    placed[node] = true;
    result.order.push_back(node);
    for (std::size_t user : users[node])
      if (--waitingOn[user] == 0) ready.insert(user);
  }
  if (result.order.size() < inputsOf.size()) result.cycle = findCycle(inputsOf, placed);
  return result;
}

}  // namespace strata::loader
