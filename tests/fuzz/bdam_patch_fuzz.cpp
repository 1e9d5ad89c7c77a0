// Fuzz target: bytes as a stored geometry.bdam patch (plugins/geometry-bdam/patch_codec.hpp), decoded, and a patch
// that decodes stored again and decoded to the same patch. Bad input must end in a PatchFormatError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "patch_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strata::bdam;
  try {
    const DisplacedPatch patch = decodePatch(std::as_bytes(std::span(data, size)));
    if (decodePatch(encodePatch(patch)) != patch) std::abort();  // a decoded patch round-trips
  } catch (const PatchFormatError&) {
  }
  return 0;
}
