#include <strata/plugin/height_slopes.hpp>

#include <strata/plugin/layer.hpp>

namespace strata {

// East, d / cos(latitude) of longitude is one footprint d along the ground (as height_sampling.glsl's
// shadingNormal steps).
std::string heightSlopesGlsl(const std::string& name, const Layer& height, const std::string& radius) {
  const std::string h = height.samplingFunction();
  return "#include \"strata/height_slopes.glsl\"\n"
         "vec2 " +
         name +
         "(SurfacePoint p, float h) {\n"
         "  float d = slopeStep(p);\n"
         "  vec2 east = vec2(d / max(cos(p.lonlat.y), 1e-4), 0.0), north = vec2(0.0, d);\n"
         "  p.lonlatDx = east;\n"
         "  p.lonlatDy = north;\n"
         "  float eastRise = slopeRise(" +
         h + "(slopeNeighbour(p, east)), h, " + h +
         "(slopeNeighbour(p, -east)));\n"
         "  float northRise = slopeRise(" +
         h + "(slopeNeighbour(p, north)), h, " + h +
         "(slopeNeighbour(p, -north)));\n"
         "  return vec2(eastRise, northRise) / (d * (" +
         radius +
         "));\n"
         "}\n";
}

}  // namespace strata
