#pragma once
#include <strata/plugin/node_type.hpp>

namespace strata::procedural {

// source.checker: a checkerboard laid on the ground around a point (checker_layer.hpp).
NodeTypeDeclaration checkerDeclaration();

}  // namespace strata::procedural
