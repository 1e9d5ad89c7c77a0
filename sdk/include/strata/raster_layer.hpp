#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <strata/gl/texture.hpp>
#include <strata/layer.hpp>
#include <strata/projection.hpp>

namespace strata {

class PluginRegistry;

// Where a raster's texels lie on the body: a projection, and GDAL's affine geotransform from the
// (column, row) of texel corners to map coordinates: x = t[0] + column t[1], y = t[3] + row t[5]. Grids
// are north-up (t[2] = t[4] = 0); t[5] is negative when row 0 is the north edge.
struct RasterGeoreference {
  std::shared_ptr<const Projection> projection;
  std::array<double, 6> geotransform{0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
};

// The georeference of a raster `width` texels wide: a periodic projection is centred on the raster, so
// that longitudes wrap into its x range (a map of [0, 360) degrees sees longitude -10 as 350).
RasterGeoreference makeGeoreference(std::unique_ptr<Projection> projection, const std::array<double, 6>& geotransform,
                                    int width);

// A longitude/latitude box in degrees. East may exceed 180 for boxes across the antimeridian.
struct GeographicExtent {
  double west = -180.0;
  double south = -90.0;
  double east = 180.0;
  double north = 90.0;
};

// The geotransform (in degrees) and the georeference of a longitude/latitude raster of `width` x `height`
// texels covering `extent`.
std::array<double, 6> geographicGeotransform(const GeographicExtent& extent, int width, int height);
RasterGeoreference geographicGeoreference(const PluginRegistry& plugins, const GeographicExtent& extent, int width,
                                          int height);

// A raster held in memory, ready for the GPU. Texels are row-major in the geotransform's row order, and
// carry their coverage (0 at nodata, 1 with data) so that filtering never mixes nodata into values:
//   channels 4 (colour kinds): linear r, g, b premultiplied by coverage, then coverage
//   channels 2 (one-channel kinds: height, scalar, luminance, mask): value x coverage, coverage
struct RasterImage {
  int width = 0;
  int height = 0;
  int channels = 2;
  std::vector<float> texels;
};

// A layer sampled from one texture through any projection (DESIGN.md "Projections"): per sample the
// projection's GLSL maps longitude/latitude to map coordinates and the geotransform maps those to the
// texture. Source plugins fill a RasterImage and hand it over; out-of-core rasters come with the page cache.
class RasterLayer : public Layer {
 public:
  RasterLayer(std::string nodeId, LayerKind kind);

  // One-channel kinds: the value a shader sees is raw x scale + offset (e.g. int16 counts to metres).
  void setValueTransform(double scale, double offset);
  // Creates the texture with its mip chain from `image`; on the GL thread.
  void upload(const RasterImage& image, RasterGeoreference georeference);

  LayerKind kind() const override { return kind_; }
  std::string samplingFunction() const override;
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;

 private:
  // What bind() gives the shader, fixed at upload.
  struct SamplingUniforms {
    std::array<glm::vec4, 2> projection{};  // Projection::glslParameters()
    glm::vec4 mapToTexture{0.0f};           // u = x * .x + .y, v = y * .z + .w (GLSL map units)
    bool repeatX = false;                   // the raster spans one period of a periodic projection
  };

  std::string prefix_;  // GLSL identifier prefix unique to the node
  LayerKind kind_;
  double scale_ = 1.0;
  double offset_ = 0.0;
  RasterGeoreference georeference_;
  SamplingUniforms uniforms_;
  Texture texture_;
};

}  // namespace strata
