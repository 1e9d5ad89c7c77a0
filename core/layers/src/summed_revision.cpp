#include <strata/plugin/layer.hpp>

namespace strata {

// Each revision only grows, so their sum grows whenever one of them does.
std::uint64_t summedRevision(const std::vector<const Layer*>& layers) {
  std::uint64_t sum = 0;
  for (const Layer* layer : layers) sum += layer->revision();
  return sum;
}

}  // namespace strata
