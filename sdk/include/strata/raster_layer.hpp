#pragma once
#include <string>
#include <vector>

#include <strata/gl/texture.hpp>
#include <strata/layer.hpp>

namespace strata {

// A geographic (longitude, latitude) box in degrees. East may exceed 180 for boxes across the antimeridian.
struct GeographicExtent {
  double west = -180.0;
  double south = -90.0;
  double east = 180.0;
  double north = 90.0;

  bool global() const { return east - west >= 360.0 - 1e-9; }
};

// A raster held in memory, ready for the GPU. Texels are row-major, row 0 at the north edge, and carry
// their coverage (0 at nodata, 1 with data) so that filtering never mixes nodata into values:
//   channels 4 (colour kinds): linear r, g, b premultiplied by coverage, then coverage
//   channels 2 (one-channel kinds: height, scalar, luminance, mask): value x coverage, coverage
struct RasterImage {
  int width = 0;
  int height = 0;
  int channels = 2;
  std::vector<float> texels;
  GeographicExtent extent;
};

// A layer sampled from one texture in the equirectangular projection. Source plugins fill a RasterImage
// and hand it over; other projections come with the page cache.
class RasterLayer : public Layer {
 public:
  RasterLayer(std::string nodeId, LayerKind kind);

  // One-channel kinds: the value a shader sees is raw x scale + offset (e.g. int16 counts to metres).
  void setValueTransform(double scale, double offset);
  // Creates the texture with its mip chain from `image`; on the GL thread.
  void upload(const RasterImage& image);

  LayerKind kind() const override { return kind_; }
  std::string samplingFunction() const override;
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;

 private:
  std::string prefix_;  // GLSL identifier prefix unique to the node
  LayerKind kind_;
  double scale_ = 1.0;
  double offset_ = 0.0;
  GeographicExtent extent_;
  Texture texture_;
};

}  // namespace strata
