#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "cube_bintree.hpp"

namespace strata::bdam {

// Two nodes of one level that share their hypotenuse (on a face or across a face's edge): the unit the builder
// simplifies [Cignoni et al. 2003, §5, "blocks of 4 triangular patches joined by their short edges"]. Its four
// children, the two halves' children, meet at the hypotenuse's midpoint; their hypotenuses are its outline, the
// halves' legs.
struct Diamond {
  std::array<BintreeNode, 2> halves;
  std::array<BintreeNode, 4> children() const;  // halves[0]'s two, then halves[1]'s
};

// A node's hypotenuse as its ends' directions, lesser first: the same bits for both halves of a diamond.
using HypotenuseKey = std::array<std::uint64_t, 6>;
HypotenuseKey hypotenuseOf(const BintreeNode& node);

// Every diamond of `level`, each node of the level in exactly one, in the order of the first half's root and path.
std::vector<Diamond> diamondsOf(int level);

}  // namespace strata::bdam
