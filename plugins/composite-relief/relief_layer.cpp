#include "relief_layer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/vec4.hpp>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/height_slopes.hpp>
#include <strata/plugin/srgb.hpp>

namespace strata::composite {

namespace {

// Flat ground's shade under a light at `altitude` degrees, sin(altitude), in either mode (Mark's weights sum
// to 2 there and are halved); at least 0.01, so that a light at the horizon, which leaves flat ground dark
// either way, divides by no zero.
float flatShade(double altitude) { return float(std::max(std::sin(altitude * std::numbers::pi / 180.0), 0.01)); }

}  // namespace

ReliefLayer::ReliefLayer(const std::string& nodeId, const Layer& height, const Layer* surface, Lighting lighting,
                         double radius)
    : prefix_("layer_" + glslIdentifier(nodeId)),
      height_(height),
      surface_(surface),
      lighting_(lighting),
      radius_(radius) {}

// Azimuth clockwise from north, altitude above the horizon: east = sin(azimuth) cos(altitude), north =
// cos(azimuth) cos(altitude), up = sin(altitude) (the convention of cartographic hillshading).
glm::vec3 ReliefLayer::lightDirection(double azimuthDegrees, double altitudeDegrees) {
  const double azimuth = azimuthDegrees * std::numbers::pi / 180.0,
               altitude = altitudeDegrees * std::numbers::pi / 180.0;
  return {float(std::sin(azimuth) * std::cos(altitude)), float(std::cos(azimuth) * std::cos(altitude)),
          float(std::sin(altitude))};
}

// What the layer shows where the height's slopes are `slopes` and `light` is the light in the ground's
// east/north/up frame: the Lambertian shade (from that light, or Mark's four), or the slope or the aspect, each
// from 0 to 1. Normalised, the shade is over flat ground's: sin(altitude), or under the sun its height over the
// point's horizon, light.z. Selected, not branched: llvmpipe would run every branch, and the shade and one
// arctangent are all any choice costs.
std::string ReliefLayer::value() const {
  const std::string& p = prefix_;
  return "float " + p + "_value(vec2 slopes, vec3 light) {\n  float level = " + p + "_sunLit == 1 && " + p +
         "_normalise == 1 ? max(light.z, 0.01) : " + p + "_flat;\n  float shade = reliefShade(slopes, " + p +
         "_exaggeration, light, " + p + "_multidirectional == 1, " + p + "_altitude) / level;\n  return " + p +
         "_output == 0 ? shade : reliefAngle(slopes, " + p + "_exaggeration, " + p + "_output == 2);\n}\n";
}

// The tint's colour where the height is `h` and its slopes `slopes`: the ramp's, by elevation (m) or by
// slope (deg), or white.
std::string ReliefLayer::tint() const {
  const std::string& p = prefix_;
  return "vec3 " + p + "_tint(vec2 slopes, float h) {\n  float x = " + p +
         "_tintBy == 1 ? h : degrees(slopeAngle(slopes, 1.0));\n  return reliefRamp(" + p + "_ramp, " + p +
         "_tintBy == 0 ? 0 : " + p + "_rampStops, x);\n}\n";
}

// The layer's value, grey where the height has data, or multiplying the surface's colour (which shows
// unshaded where the height has none). The height and its slopes are sampled once (for procedural heights,
// whose slopes cost four more samples, loops of noise that llvmpipe's compiler takes minutes over when
// inlined twice more).
std::string ReliefLayer::shadingGlsl() const {
  const std::string& p = prefix_;
  const std::string shade =
      "  vec2 slopes = height.gb;\n"
      "  vec3 shade = " +
      p + "_tint(slopes, height.r) * " + p + "_value(slopes, light);\n";
  if (!surface_) return "  if (height.a <= 0.0) return vec4(0.0);\n" + shade + "  return vec4(shade, height.a);\n";
  return "  vec4 surface = " + surface_->samplingFunction() +
         "(p);\n"
         "  if (height.a <= 0.0) return " +
         p + "_multiply == 0 ? vec4(0.0) : surface;\n" + shade + "  if (" + p +
         "_multiply == 0) return vec4(shade, height.a);\n"
         "  return vec4(surface.rgb * mix(vec3(1.0), shade, height.a), surface.a);\n";
}

std::string ReliefLayer::glsl() const {
  const std::string& p = prefix_;
  return height_.glslOnce() + (surface_ ? surface_->glslOnce() : std::string()) +
         "#include \"composite-relief/relief.glsl\"\n"
         "uniform vec3 " +
         p +
         "_light;\n"
         "uniform vec3 " +
         p +
         "_sun;\n"
         "uniform int " +
         p +
         "_sunLit;\n"
         "uniform int " +
         p +
         "_normalise;\n"
         "uniform float " +
         p +
         "_exaggeration;\n"
         "uniform float " +
         p +
         "_radius;\n"
         "uniform float " +
         p +
         "_altitude;\n"
         "uniform int " +
         p +
         "_multiply;\n"
         "uniform int " +
         p +
         "_multidirectional;\n"
         "uniform float " +
         p +
         "_flat;\n"
         "uniform int " +
         p +
         "_output;\n"
         "uniform int " +
         p +
         "_tintBy;\n"
         "uniform int " +
         p +
         "_rampStops;\n"
         "uniform vec4 " +
         p + "_ramp[RELIEF_RAMP_STOPS];\n" + heightSlopesGlsl(p + "_slopes", height_, p + "_radius") + value() +
         tint() + "vec4 " + p +
         "(SurfacePoint p) {\n"
         "  vec3 light = " +
         p + "_sunLit == 1 ? reliefLocalDirection(p, " + p + "_sun) : " + p +
         "_light;\n"
         "  vec4 height = " +
         p + "_slopes(p);\n" + shadingGlsl() + "}\n";
}

void ReliefLayer::bind(ShaderProgram& program, TextureUnits& units) const {
  height_.bind(program, units);
  if (surface_) surface_->bind(program, units);
  program.set(prefix_ + "_light", lightDirection(lighting_.azimuth, lighting_.altitude));
  program.set(prefix_ + "_sun", sun_);
  program.set(prefix_ + "_sunLit", lighting_.sun ? 1 : 0);
  program.set(prefix_ + "_normalise", lighting_.normalised ? 1 : 0);
  program.set(prefix_ + "_exaggeration", float(lighting_.exaggeration));
  program.set(prefix_ + "_radius", float(radius_));
  program.set(prefix_ + "_altitude", float(lighting_.altitude * std::numbers::pi / 180.0));
  program.set(prefix_ + "_multiply", lighting_.multiply ? 1 : 0);
  program.set(prefix_ + "_multidirectional", lighting_.multidirectional ? 1 : 0);
  program.set(prefix_ + "_flat", lighting_.normalised ? flatShade(lighting_.altitude) : 1.0f);
  program.set(prefix_ + "_output", int(lighting_.output));
  bindRamp(program);
}

// The ramp's stops, their colours decoded to scene-linear light to blend as the output does.
void ReliefLayer::bindRamp(ShaderProgram& program) const {
  const std::vector<double>& stops = lighting_.tint.stops;
  program.set(prefix_ + "_tintBy", int(lighting_.tint.by));
  program.set(prefix_ + "_rampStops", int(stops.size() / 4));
  for (std::size_t i = 0; i + 3 < stops.size(); i += 4)
    program.set(prefix_ + "_ramp[" + std::to_string(i / 4) + "]",
                glm::vec4(float(stops[i]), srgbToSceneLinear(stops[i + 1], stops[i + 2], stops[i + 3])));
}

void ReliefLayer::setPageDemand(PageDemand demand) const {
  height_.setPageDemand(demand);
  if (surface_) surface_->setPageDemand(demand);
}

}  // namespace strata::composite
