#pragma once
#include <strata/export.hpp>
#include <vector>

#include <strata/plugin/projection.hpp>

// Not part of the SDK: exported from libstrata_core for Strata's own tests and tools.
STRATA_EXPORTS_BEGIN
namespace strata {

// The projections built into Strata (docs/architecture.md, "Projections"): equirectangular, polar-stereographic,
// healpix, orthographic and perspective.
std::vector<ProjectionDeclaration> builtinProjections();

}  // namespace strata
STRATA_EXPORTS_END
