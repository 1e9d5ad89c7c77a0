#include "colour_encoding.hpp"

#include "source_gdal_settings.hpp"

namespace strata::gdal {
namespace {

// Whether the pipeline gives the value at `where` itself: a default's location is the node's.
bool given(const NodeSetup& setup, const SourceLocation& where) {
  return where.file != setup.where.file || where.line != setup.where.line || where.column != setup.where.column;
}

}  // namespace

std::optional<ColourEncoding> colourEncodingOf(const NodeSetup& setup, const GdalSettings& settings) {
  const SourceLocation& where = gdalParameters().where(setup.parameters, &GdalSettings::colorspace);
  if (settings.kind != LayerKind::Color) {
    if (given(setup, where))
      throw Error(where,
                  std::string("a ") + toString(settings.kind) + " layer holds values, which have no colour space",
                  "remove `colorspace`, or read the raster as colours with `kind: color`");
    return std::nullopt;
  }
  const ColourConfig config =
      ColourConfig::load(setup.colour.config, setup.colour.config.empty() ? setup.where : setup.colour.where);
  const std::string& space = settings.colorspace;
  if (config.isSceneLinear(space, where)) return std::nullopt;
  ColourEncoding encoding{config, space, where};
  encoding.toSceneLinearGlsl("strata_toSceneLinear");  // refuses, at its line, a conversion the GPU cannot run
  return encoding;
}

}  // namespace strata::gdal
