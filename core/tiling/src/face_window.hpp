#pragma once
// The window of one HEALPix face that a pyramid finer than the whole strip allows (healpix::kMostNside)
// holds: the part of the face the input covers.
#include <cstdint>

#include <gdal_priv.h>

#include <strata/error.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/projection.hpp>

namespace strata::tiling {

// The level-0 texels of the one face at `nside` that `input` covers, with a margin, found by mapping a
// grid of the input's texel corners through `strip` (healpix::stripProjection). Throws strata::Error at
// `where` when the input reaches more than one face, or more of a face than a GeoTIFF holds.
healpix::FaceWindow faceWindowCovering(GDALDataset& input, const Projection& strip, std::int64_t nside,
                                       const SourceLocation& where);

}  // namespace strata::tiling
