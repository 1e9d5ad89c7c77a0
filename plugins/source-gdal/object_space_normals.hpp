#pragma once
#include <string>

#include <strata/plugin/layer.hpp>

namespace strata::gdal {

// An object-space normal map (source.gdal's normal_space: object) as the tangent-space layer every consumer of
// normal layers reads: each texel's normal is given in the body's planet-fixed axes (red x, toward longitude 0
// on the equator; green y; blue z, north; 0 to full scale for -1 to 1), and the sampling function turns it
// into the east/north/up frame of the ground where it is sampled.
class ObjectSpaceNormals : public Layer {
 public:
  // `raster`: the layer that reads the map's texels as they are; it outlives this one.
  ObjectSpaceNormals(const Layer& raster, const std::string& nodeId);

  LayerKind kind() const override { return LayerKind::Normal; }
  std::string samplingFunction() const override { return function_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override { raster_.bind(program, units); }
  void setPageDemand(PageDemand demand) const override { raster_.setPageDemand(demand); }
  std::uint64_t revision() const override { return raster_.revision(); }

 private:
  const Layer& raster_;
  std::string function_;
};

}  // namespace strata::gdal
