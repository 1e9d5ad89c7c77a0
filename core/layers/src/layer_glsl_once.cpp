#include <strata/plugin/layer.hpp>

namespace strata {

std::string Layer::glslOnce() const {
  const std::string guard = "STRATA_LAYER_" + samplingFunction();
  return "#ifndef " + guard + "\n#define " + guard + "\n" + glsl() + "#endif\n";
}

}  // namespace strata
