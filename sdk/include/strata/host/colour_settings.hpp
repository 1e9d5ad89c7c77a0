#pragma once
#include <filesystem>
#include <strata/export.hpp>

#include <strata/error.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The pipeline's `colour:` section (docs/colour.md): which OpenColorIO config colours are managed with.
struct ColourSettings {
  std::filesystem::path config;  // empty: $OCIO's config, else Strata's own (ColourConfig::load)
  SourceLocation where;          // the `config` value, for messages
};

}  // namespace strata
STRATA_EXPORTS_END
