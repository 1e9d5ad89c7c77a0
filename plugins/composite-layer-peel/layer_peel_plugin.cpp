// composite-layer-peel: stacked height layers peeled apart and seen in relation to each other (seed 000
// section 1.1 and chapter 6, layered data peeling; digest 000 section 6).
#include <strata/plugin.hpp>

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
