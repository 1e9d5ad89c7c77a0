// composite-layer-peel: stacked height layers peeled apart and seen in relation to each other
// ([Kooima 2008, §1.1, ch. 6], layered data peeling).
#include <strata/plugin/plugin.hpp>

#include "declarations.hpp"

namespace strata::composite {
namespace {

void registerTypes(PluginRegistrar& registrar) {
  registrar.add(layerPeelDeclaration());
  registrar.add(peeledSurfaceDeclaration());
}

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-layer-peel", "0.1.0", strata::composite::registerTypes)
