#include <strata/plugin/node.hpp>

namespace strata {

Node* NodeSetup::input(const std::string& port) const {
  auto found = inputs.find(port);
  return found == inputs.end() || found->second.empty() ? nullptr : found->second.front();
}

const std::vector<Node*>& NodeSetup::inputList(const std::string& port) const {
  static const std::vector<Node*> none;
  auto found = inputs.find(port);
  return found == inputs.end() ? none : found->second;
}

}  // namespace strata
