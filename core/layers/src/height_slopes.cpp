#include <strata/plugin/height_slopes.hpp>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>

namespace strata {
namespace {

// The footprint one step of `d` along the ground wide each way, the scale differences over it resolve: detail a
// grazing footprint's anisotropic taps would add does not show in them (east, d / cos(latitude) of longitude is
// one footprint d along the ground, as height_sampling.glsl's shadingNormal steps).
const char* const kSlopeFootprint =
    "  float d = groundFootprint(p);\n"
    "  p.lonlatDx = vec2(d / max(cos(p.lonlat.y), 1e-4), 0.0);\n"
    "  p.lonlatDy = vec2(0.0, d);\n";

// A layer that gives its slopes with its value (SlopedLayer): one sample, its change per radian over the radius.
std::string slopedSampleGlsl(const std::string& name, const std::string& sloped, const std::string& radius) {
  return "vec4 " + name + "(SurfacePoint p) {\n" + kSlopeFootprint + "  vec4 s = " + sloped +
         "(p);\n  return vec4(s.r, s.gb / (" + radius + "), s.a);\n}\n";
}

// Any other: central differences of its samples one footprint away each way along the ground, each over that
// footprint.
std::string neighbourSamplesGlsl(const std::string& name, const std::string& h, const std::string& radius) {
  return "vec4 " + name +
         "(SurfacePoint p) {\n"
         "  vec4 height = " +
         h + "(p);\n" + "  if (height.a <= 0.0) return vec4(0.0);\n" + kSlopeFootprint +
         "  vec2 east = p.lonlatDx, north = p.lonlatDy;\n"
         "  float eastRise = slopeRise(" +
         h + "(slopeNeighbour(p, east)), height.r, " + h +
         "(slopeNeighbour(p, -east)));\n"
         "  float northRise = slopeRise(" +
         h + "(slopeNeighbour(p, north)), height.r, " + h +
         "(slopeNeighbour(p, -north)));\n"
         "  return vec4(height.r, vec2(eastRise, northRise) / (d * (" +
         radius + ")), height.a);\n}\n";
}

}  // namespace

std::string heightSlopesGlsl(const std::string& name, const Layer& height, const std::string& radius) {
  const std::string sloped = slopedSamplingFunctionOf(height);
  return "#include \"strata/height_slopes.glsl\"\n" +
         (sloped.empty() ? neighbourSamplesGlsl(name, height.samplingFunction(), radius)
                         : slopedSampleGlsl(name, sloped, radius));
}

}  // namespace strata
