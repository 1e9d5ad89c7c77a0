#pragma once
#include <array>
#include <memory>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/gl/texture.hpp>
#include <strata/plugin/projected_raster_layer.hpp>
#include <strata/plugin/raster_georeference.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

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

// A layer sampled from one texture through any projection (docs/architecture.md, "Projections"): per sample
// the projection's GLSL maps longitude/latitude to map coordinates and the geotransform maps those to the
// texture. Source plugins fill a RasterImage and hand it over; rasters too large for one texture go
// through the page cache (PagedRasterLayer).
class RasterLayer : public ProjectedRasterLayer {
 public:
  RasterLayer(std::string nodeId, LayerKind kind);

  // Creates the texture with its mip chain from `image`; on the GL thread.
  void upload(const RasterImage& image, RasterGeoreference georeference);

  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;

 private:
  Texture texture_;
};

}  // namespace strata
STRATA_EXPORTS_END
