#pragma once
#include <cstdint>

#include "gdal_page_source.hpp"

namespace strata::gdal {

// The pages of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp), read with GDAL as any raster's, down to faces
// of one page: each page lies on one face, and its border beyond the face's edge comes from the
// neighbouring face on the sphere, so that filtering is seamless across the faces' edges.
class HealpixPageSource final : public GdalPageSource {
 public:
  HealpixPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind, std::optional<ColourEncoding> encoding,
                    std::int64_t nside);

  LevelWindow gridOf(const PageKey& key) const override;
  std::optional<glm::ivec2> texelBeside(const PageKey& key, glm::ivec2 texel) const override;

 private:
  int faceSide(int level) const { return int(nside_ >> level); }
  int faceOf(const PageKey& key) const { return key.column * kPagePayload / faceSide(key.level); }

  std::int64_t nside_;
};

}  // namespace strata::gdal
