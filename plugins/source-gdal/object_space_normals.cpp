#include "object_space_normals.hpp"

namespace strata::gdal {

ObjectSpaceNormals::ObjectSpaceNormals(const Layer& raster, const std::string& nodeId)
    : raster_(raster), function_("objectSpaceNormals_" + glslIdentifier(nodeId)) {}

// The map's normal, blended by the raster's filtering in planet-fixed axes, renormalised and seen from the
// ground's own frame at the point (strata/local_frame.glsl); coverage as the raster gives it.
std::string ObjectSpaceNormals::glsl() const {
  return raster_.glslOnce() + "#include \"strata/local_frame.glsl\"\n" + "vec4 " + function_ +
         "(SurfacePoint p) {\n"
         "  vec4 texel = " +
         raster_.samplingFunction() +
         "(p);\n"
         "  if (texel.a <= 0.0) return texel;\n"
         "  vec3 planetFixed = normalize(texel.rgb * 2.0 - 1.0);\n"
         "  return vec4(planetFixed * eastNorthUp(p.lonlat.x, p.normal) * 0.5 + 0.5, texel.a);\n"
         "}\n";
}

}  // namespace strata::gdal
