#include "grid_size.hpp"

#include <charconv>

namespace strata::pgm {
namespace {

std::optional<int> side(const char* first, const char* last) {
  int value = 0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || value < kLeastGridSide || value > kGreatestGridSide) return std::nullopt;
  return value;
}

}  // namespace

std::optional<glm::ivec2> parseGridSize(const std::string& text) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const std::optional<int> columns = side(text.data(), text.data() + x);
  const std::optional<int> rows = side(text.data() + x + 1, text.data() + text.size());
  if (!columns || !rows) return std::nullopt;
  return glm::ivec2(*columns, *rows);
}

}  // namespace strata::pgm
