#include <cctype>

#include <strata/plugin/layer.hpp>

namespace strata {

std::string glslIdentifier(const std::string& nodeId) {
  std::string out;
  for (char c : nodeId) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  // GLSL reserves identifiers with two consecutive underscores; squeeze them.
  std::string squeezed;
  for (char c : out)
    if (!(c == '_' && !squeezed.empty() && squeezed.back() == '_')) squeezed += c;
  return squeezed;
}

}  // namespace strata
