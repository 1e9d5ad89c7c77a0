#include "colour_encoding.hpp"

namespace strata::gdal {
namespace {

// Whether the pipeline gives `name` itself: a default's location is the node's.
bool given(const NodeSetup& setup, const std::string& name) {
  const SourceLocation& where = setup.parameters.where(name);
  return where.file != setup.where.file || where.line != setup.where.line || where.column != setup.where.column;
}

}  // namespace

std::optional<ColourEncoding> colourEncodingOf(const NodeSetup& setup, LayerKind kind) {
  const SourceLocation& where = setup.parameters.where("colorspace");
  if (kind != LayerKind::Color) {
    if (given(setup, "colorspace"))
      throw Error(where, std::string("a ") + toString(kind) + " layer holds values, which have no colour space",
                  "remove `colorspace`, or read the raster as colours with `kind: color`");
    return std::nullopt;
  }
  const ColourConfig config =
      ColourConfig::load(setup.colour.config, setup.colour.config.empty() ? setup.where : setup.colour.where);
  const std::string& space = setup.parameters.string("colorspace");
  if (config.isSceneLinear(space, where)) return std::nullopt;
  ColourEncoding encoding{config, space, where};
  encoding.toSceneLinearGlsl("strata_toSceneLinear");  // refuses, at its line, a conversion the GPU cannot run
  return encoding;
}

}  // namespace strata::gdal
