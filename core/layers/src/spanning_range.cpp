#include <algorithm>

#include <strata/plugin/layer.hpp>

namespace strata {

std::optional<ValueRange> spanningRange(const std::vector<const Layer*>& layers) {
  std::optional<ValueRange> range;
  for (const Layer* layer : layers) {
    const std::optional<ValueRange> own = layer->valueRange();
    if (!own) return std::nullopt;
    range = range ? ValueRange{std::min(range->least, own->least), std::max(range->greatest, own->greatest)} : *own;
  }
  return range;
}

}  // namespace strata
