#include <strata/plugin/height_input.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/node.hpp>
#include <strata/plugin/spherical_cap.hpp>

namespace strata {
namespace {

// Metres as a user would type them: 240000, not 2.4e+05.
std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", value);
  return text;
}

// The bounds given, which bound only a height layer: without one, none.
HeightBounds givenOf(const NodeSetup& setup) {
  if (!setup.input("height")) return {};
  return HeightInput::bounds().read(setup.parameters);
}

}  // namespace

PortDeclaration HeightInput::port() {
  return {.name = "height",
          .type = PortType::Layer,
          .kinds = {LayerKind::Height},
          .optional = true,
          .doc = "heights in metres above the body's radius; none: the bare sphere"};
}

std::vector<ParameterDeclaration> HeightInput::parameters() { return bounds().declarations(); }

void HeightInput::declareOn(NodeTypeDeclaration& type) {
  type.inputs.push_back(port());
  for (ParameterDeclaration& parameter : parameters()) type.parameters.push_back(std::move(parameter));
}

const ParameterBindings<HeightBounds>& HeightInput::bounds() {
  using S = HeightBounds;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::lowest, {.name = "lowest",
                            .units = "m",
                            .doc = "no height lies below this; culling and reference spheres trust it (unset: the "
                                   "height layer's least, or 0 if that is higher)"})
          .add(&S::highest, {.name = "highest",
                             .units = "m",
                             .doc = "no height lies above this; culling and reference spheres trust it (unset: the "
                                    "height layer's greatest, or 0 if that is lower)"});
  return bindings;
}

HeightInput::HeightInput(const NodeSetup& setup)
    : layer_(setup.input("height") ? setup.input("height")->layer() : nullptr),
      given_(givenOf(setup)),
      where_(setup.where),
      highestWhere_(given_.highest ? bounds().where(setup.parameters, &HeightBounds::highest) : setup.where) {
  if (given_.lowest && given_.highest && *given_.lowest > *given_.highest)
    throw Error(
        bounds().where(setup.parameters, &HeightBounds::lowest),
        "lowest (" + formatValue(*given_.lowest) + " m) lies above highest (" + formatValue(*given_.highest) + " m)",
        "give the height layer's least and greatest heights, least first");
}

HeightRange HeightInput::open() {
  if (!layer_) return range_ = {};
  const std::optional<ValueRange> known = layer_->valueRange();
  if (!known && (!given_.lowest || !given_.highest))
    throw Error(where_,
                "the height layer does not know the least and greatest heights it holds, which culling must trust",
                "write the raster with `strata tile FILE OUT.tif`, which stores its heights region by region, or set "
                "lowest: and highest: (m) on this node, or store the raster's statistics with gdalinfo -stats FILE");
  if (known) checkGivenHold(*known);
  // Given values hold the known ones (checkGivenHold), so the range is never turned over.
  range_ = {given_.lowest.value_or(std::min(known ? known->least : 0.0, 0.0)),
            given_.highest.value_or(std::max(known ? known->greatest : 0.0, 0.0))};
  return range_;
}

bool HeightInput::boundsRegions() const {
  const auto* regional = layer_ ? layer_->as<RegionalValueLayer>() : nullptr;
  return regional && regional->valuesWithin(SphericalCap{glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi}).has_value();
}

RegionalHeights HeightInput::within(const SphericalCap& cap) const {
  const auto* regional = layer_ ? layer_->as<RegionalValueLayer>() : nullptr;
  const std::optional<ValueRange> known = regional ? regional->valuesWithin(cap) : std::nullopt;
  if (!known) return {range_};
  const HeightRange there{std::max(known->least, range_.lowest), std::min(known->greatest, range_.highest)};
  if (there.lowest > there.highest) return {range_};
  return {there, known->finest};
}

void HeightInput::checkGivenHold(const ValueRange& known) const {
  if ((!given_.lowest || known.least >= *given_.lowest) && (!given_.highest || known.greatest <= *given_.highest))
    return;
  const double least = std::min(known.least, given_.lowest.value_or(known.least));
  const double greatest = std::max(known.greatest, given_.highest.value_or(known.greatest));
  throw Error(highestWhere_,
              "the height layer reaches from " + metres(known.least) + " to " + metres(known.greatest) +
                  " m, beyond lowest or highest: the generator would cut off terrain that shows",
              "set lowest: " + metres(std::floor(least)) + " and highest: " + metres(std::ceil(greatest)) +
                  " on this node, or leave both out to take the layer's own");
}

std::map<std::string, std::string> HeightInput::substitutions() const {
  if (!layer_) return {{"STRATA_PROGRAM_DEFINES", ""}, {"STRATA_HEIGHT_LAYER_GLSL", ""}};
  const std::string byFace = faceSamplingFunctionOf(*layer_), sloped = slopedSamplingFunctionOf(*layer_);
  return {{"STRATA_PROGRAM_DEFINES", "#define STRATA_HAS_HEIGHT\n#define STRATA_HEIGHT_FUNCTION " +
                                         layer_->samplingFunction() +
                                         (byFace.empty() ? "" : "\n#define STRATA_HEIGHT_FACE_FUNCTION " + byFace) +
                                         (sloped.empty() ? "" : "\n#define STRATA_HEIGHT_SLOPED_FUNCTION " + sloped)},
          {"STRATA_HEIGHT_LAYER_GLSL", layer_->glslOnce()}};
}

}  // namespace strata
