#include "healpix_page_source.hpp"

#include <strata/plugin/healpix_pyramid.hpp>

namespace strata::gdal {

HealpixPageSource::HealpixPageSource(std::unique_ptr<GDALDataset> dataset, LayerKind kind,
                                     std::optional<ColourEncoding> encoding, std::int64_t nside)
    : GdalPageSource(std::move(dataset), kind, std::move(encoding), healpix::stripPyramid(nside)), nside_(nside) {}

LevelWindow HealpixPageSource::gridOf(const PageKey& key) const {
  const int side = faceSide(key.level);
  return {key.level, faceOf(key) * side, 0, side, side};
}

std::optional<glm::ivec2> HealpixPageSource::texelBeside(const PageKey& key, glm::ivec2 texel) const {
  return healpix::texelAcross(faceSide(key.level), faceOf(key), texel);
}

}  // namespace strata::gdal
