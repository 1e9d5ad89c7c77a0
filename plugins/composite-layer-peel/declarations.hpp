#pragma once
#include <strata/plugin/node_type.hpp>

namespace strata::composite {

// The plugin's two node types: the peeled heights, and the colours of what they show.
NodeTypeDeclaration layerPeelDeclaration();
NodeTypeDeclaration peeledSurfaceDeclaration();

}  // namespace strata::composite
