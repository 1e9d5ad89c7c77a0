#pragma once
#include <exception>
#include <string>

#include <strata/error.hpp>
#include <strata/host/pipeline.hpp>

namespace strata {

// Runs `work` for a node; anything it throws that is not already a strata::Error becomes one that names
// the node, its type and what it was doing, so a faulty plugin or unreadable data never escapes unnamed,
// even where a plugin throws something that is no std::exception.
template <typename Work>
auto guardNode(const NodeDescription& node, const std::string& doing, Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& failure) {
    throw Error(node.where, "node '" + node.id + "' (" + node.type + ") " + doing + ": " + failure.what());
  } catch (...) {
    throw Error(node.where,
                "node '" + node.id + "' (" + node.type + ") " + doing +
                    ": its plugin threw something that is no std::exception",
                "report it to the plugin's authors");
  }
}

}  // namespace strata
