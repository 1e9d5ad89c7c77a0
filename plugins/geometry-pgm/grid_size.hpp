#pragma once
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace strata::pgm {

// The grid's sides a pipeline may ask for: 2 points make one cell; 4096 x 4096 points take 768 MiB of
// vertex, index and cast buffers, beyond what any screen needs (the thesis went to 1024 x 1024).
constexpr int kLeastGridSide = 2;
constexpr int kGreatestGridSide = 4096;

// "512x512" (columns x rows) as a pipeline writes `grid`; none unless it is two whole numbers within the
// bounds joined by an x.
std::optional<glm::ivec2> parseGridSize(const std::string& text);

}  // namespace strata::pgm
