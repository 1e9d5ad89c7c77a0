#pragma once
#include <strata/body.hpp>
#include <strata/plugin/parameter.hpp>

namespace strata::loader {

// The scene's body from its `body:` section: a named body of the solar system takes its mean radius
// (strata/named_bodies.hpp) unless the section gives one. Throws strata::Error at the entry for a name
// Strata does not know given without a radius, and for a radius that is a known body's in kilometres; warns
// (strata/log.hpp) where a named body is given a radius that is not its own, which is then drawn.
Body bodyOf(const ParameterSet& section);

}  // namespace strata::loader
