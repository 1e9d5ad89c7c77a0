#pragma once
#include <optional>
#include <string>

#include <strata/colour_config.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/port.hpp>

namespace strata::gdal {

// The colour space a colour raster's values are encoded in (source.gdal's `colorspace`), one of the
// pipeline's OpenColorIO config (docs/colour.md). Pages hold the encoded values; the page cache converts
// them to scene-linear on the GPU with OpenColorIO's GLSL (PageSource::toSceneLinearGlsl).
struct ColourEncoding {
  ColourConfig config;
  std::string space;
  SourceLocation where;  // the `colorspace` value

  std::string toSceneLinearGlsl(const std::string& functionName) const {
    return config.toSceneLinear(space, functionName, where);
  }
};

struct GdalSettings;

// The encoding `colorspace` gives a layer of `kind` (source_gdal_settings.hpp), checked against the pipeline's
// config when the pipeline loads; none where its values need no conversion (a scene-linear or data space,
// or a kind that is not colour). Throws strata::Error at the `colorspace` line for a space the config lacks
// (listing those it has), one whose conversion the GPU cannot run, and a `colorspace` given to a kind that
// holds values, not colours.
std::optional<ColourEncoding> colourEncodingOf(const NodeSetup& setup, const GdalSettings& settings);

}  // namespace strata::gdal
