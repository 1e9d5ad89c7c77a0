#include <strata/height_input.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include <strata/layer.hpp>
#include <strata/node.hpp>
#include <strata/spherical_cap.hpp>

namespace strata {
namespace {

// Metres as a user would type them: 240000, not 2.4e+05.
std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", value);
  return text;
}

std::optional<double> given(const NodeSetup& setup, const std::string& name) {
  if (!setup.input("height") || !setup.parameters.has(name)) return std::nullopt;
  return setup.parameters.real(name);
}

}  // namespace

PortDeclaration HeightInput::port() {
  return {.name = "height",
          .type = PortType::Layer,
          .kinds = {LayerKind::Height},
          .optional = true,
          .doc = "heights in metres above the body's radius; none: the bare sphere"};
}

// Optional: the height layer's own range is exact (a raster's statistics or every texel counted, the
// analytic bound of procedural relief, the union of a compositor's inputs), and a range wider than the
// terrain only costs culling.
std::vector<ParameterDeclaration> HeightInput::parameters() {
  return {
      {.name = "lowest",
       .type = ParameterType::Real,
       .units = "m",
       .doc = "no height lies below this; culling and reference spheres trust it (unset: the height layer's least, "
              "or 0 if that is higher)",
       .optional = true},
      {.name = "highest",
       .type = ParameterType::Real,
       .units = "m",
       .doc = "no height lies above this; culling and reference spheres trust it (unset: the height layer's "
              "greatest, or 0 if that is lower)",
       .optional = true},
  };
}

HeightInput::HeightInput(const NodeSetup& setup)
    : layer_(setup.input("height") ? setup.input("height")->layer() : nullptr),
      lowest_(given(setup, "lowest")),
      highest_(given(setup, "highest")),
      where_(setup.where),
      highestWhere_(setup.parameters.has("highest") ? setup.parameters.where("highest") : setup.where) {
  if (lowest_ && highest_ && *lowest_ > *highest_)
    throw Error(setup.parameters.where("lowest"),
                "lowest (" + formatValue(*lowest_) + " m) lies above highest (" + formatValue(*highest_) + " m)",
                "give the height layer's least and greatest heights, least first");
}

HeightRange HeightInput::open() {
  if (!layer_) return range_ = {};
  const std::optional<ValueRange> known = layer_->valueRange();
  if (!known && (!lowest_ || !highest_))
    throw Error(where_,
                "the height layer does not know the least and greatest heights it holds, which culling must trust",
                "write the raster with `strata tile FILE OUT.tif`, which stores its heights region by region, or set "
                "lowest: and highest: (m) on this node, or store the raster's statistics with gdalinfo -stats FILE");
  if (known) checkGivenHold(*known);
  // Given values hold the known ones (checkGivenHold), so the range is never turned over.
  range_ = {lowest_.value_or(std::min(known ? known->least : 0.0, 0.0)),
            highest_.value_or(std::max(known ? known->greatest : 0.0, 0.0))};
  return range_;
}

bool HeightInput::boundsRegions() const {
  return layer_ && layer_->valuesWithin(SphericalCap{glm::dvec3(0.0, 0.0, 1.0), std::numbers::pi}).has_value();
}

HeightRange HeightInput::within(const SphericalCap& cap) const {
  const std::optional<ValueRange> known = layer_ ? layer_->valuesWithin(cap) : std::nullopt;
  if (!known) return range_;
  const HeightRange there{std::max(known->least, range_.lowest), std::min(known->greatest, range_.highest)};
  return there.lowest <= there.highest ? there : range_;
}

void HeightInput::checkGivenHold(const ValueRange& known) const {
  if ((!lowest_ || known.least >= *lowest_) && (!highest_ || known.greatest <= *highest_)) return;
  const double least = std::min(known.least, lowest_.value_or(known.least));
  const double greatest = std::max(known.greatest, highest_.value_or(known.greatest));
  throw Error(highestWhere_,
              "the height layer reaches from " + metres(known.least) + " to " + metres(known.greatest) +
                  " m, beyond lowest or highest: the generator would cut off terrain that shows",
              "set lowest: " + metres(std::floor(least)) + " and highest: " + metres(std::ceil(greatest)) +
                  " on this node, or leave both out to take the layer's own");
}

std::map<std::string, std::string> HeightInput::substitutions() const {
  if (!layer_) return {{"STRATA_PROGRAM_DEFINES", ""}, {"STRATA_HEIGHT_LAYER_GLSL", ""}};
  const std::string byFace = layer_->faceSamplingFunction();
  return {{"STRATA_PROGRAM_DEFINES", "#define STRATA_HAS_HEIGHT\n#define STRATA_HEIGHT_FUNCTION " +
                                         layer_->samplingFunction() +
                                         (byFace.empty() ? "" : "\n#define STRATA_HEIGHT_FACE_FUNCTION " + byFace)},
          {"STRATA_HEIGHT_LAYER_GLSL", layer_->glslOnce()}};
}

}  // namespace strata
