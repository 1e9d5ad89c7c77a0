#pragma once
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

#include "displaced_patch.hpp"

namespace strata::bdam {

// A patch as its file stores it [Cignoni et al. 2003, §4.4]: "quantize the barycentric coordinates to 12 bits,
// reorder vertices in strip occurrence order, delta encode them, and compress the result" with LZO. Here: the vertex
// count and the index count, each vertex's barycentrics and displacement as differences from the vertex before, then
// each index as its difference from the one before, all as zigzag varints (small differences of either sign in one
// byte), compressed by zstd at a fast level with its content checksum, so that damage shows when it is read. The
// vertices are stored in the order given: the builder puts them in the order the triangles first name them
// (meshoptimizer's vertex fetch order), which keeps consecutive vertices near each other. decodePatch(encodePatch(p))
// is p, exactly.
std::vector<std::byte> encodePatch(const DisplacedPatch& patch);  // checkPatch first: std::invalid_argument

// What is wrong with stored bytes that are not a patch: a damaged or truncated file.
class PatchFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The patch `bytes` store; throws PatchFormatError saying what is wrong with them.
DisplacedPatch decodePatch(std::span<const std::byte> bytes);

}  // namespace strata::bdam
