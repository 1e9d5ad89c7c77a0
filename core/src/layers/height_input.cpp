#include <strata/height_input.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <strata/layer.hpp>
#include <strata/node.hpp>

namespace strata {
namespace {

// Metres as a user would type them: 240000, not 2.4e+05.
std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", value);
  return text;
}

HeightRange declaredRange(const NodeSetup& setup) {
  if (!setup.input("height")) return {};
  const HeightRange range{setup.parameters.real("lowest"), setup.parameters.real("highest")};
  if (range.lowest > range.highest)
    throw Error(setup.parameters.where("lowest"),
                "lowest (" + formatValue(range.lowest) + " m) lies above highest (" + formatValue(range.highest) +
                    " m)",
                "give the height layer's least and greatest heights, least first");
  return range;
}

}  // namespace

PortDeclaration HeightInput::port() {
  return {.name = "height", .type = PortType::Layer, .kinds = {LayerKind::Height}, .optional = true,
          .doc = "heights in metres above the body's radius; none: the bare sphere"};
}

std::vector<ParameterDeclaration> HeightInput::parameters() {
  return {
      {.name = "lowest", .type = ParameterType::Real, .defaultValue = -11000.0, .units = "m",
       .doc = "no height lies below this; culling and reference spheres trust it (the default is below Earth's "
              "deepest trench)"},
      {.name = "highest", .type = ParameterType::Real, .defaultValue = 22000.0, .units = "m",
       .doc = "no height lies above this; culling and reference spheres trust it (the default is above Olympus "
              "Mons)"},
  };
}

HeightInput::HeightInput(const NodeSetup& setup)
    : layer_(setup.input("height") ? setup.input("height")->layer() : nullptr),
      range_(declaredRange(setup)),
      highestWhere_(setup.parameters.where("highest")) {}

void HeightInput::checkLayerWithin() const {
  if (!layer_) return;
  const std::optional<ValueRange> known = layer_->valueRange();
  if (!known || (known->least >= range_.lowest && known->greatest <= range_.highest)) return;
  throw Error(highestWhere_,
              "the height layer reaches from " + metres(known->least) + " to " + metres(known->greatest) +
                  " m, beyond lowest (" + metres(range_.lowest) + " m) or highest (" + metres(range_.highest) +
                  " m): the generator would cut off terrain that shows",
              "set lowest: " + metres(std::floor(std::min(known->least, range_.lowest))) + " and highest: " +
                  metres(std::ceil(std::max(known->greatest, range_.highest))) + " on this node");
}

std::map<std::string, std::string> HeightInput::substitutions() const {
  if (!layer_) return {{"STRATA_PROGRAM_DEFINES", ""}, {"STRATA_HEIGHT_LAYER_GLSL", ""}};
  const std::string byFace = layer_->faceSamplingFunction();
  return {{"STRATA_PROGRAM_DEFINES",
           "#define STRATA_HAS_HEIGHT\n#define STRATA_HEIGHT_FUNCTION " + layer_->samplingFunction() +
               (byFace.empty() ? "" : "\n#define STRATA_HEIGHT_FACE_FUNCTION " + byFace)},
          {"STRATA_HEIGHT_LAYER_GLSL", layer_->glslOnce()}};
}

}  // namespace strata
