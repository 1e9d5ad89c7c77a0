#pragma once
#include <filesystem>

#include "observation.hpp"
#include "planet_model.hpp"

namespace strata::testdata {

// Which files an observation makes: <name>-height.tif (Float32 metres, nodata -32768) and
// <name>-color.tif (8-bit sRGB RGBA, alpha 0 at nodata), or the colour file only.
enum class Products { HeightAndColour, ColourOnly };

// The nodata value of the height rasters: the int16 minimum, as planetary DEMs often use.
inline constexpr double kHeightNodata = -32768.0;

// The GeoTIFF metadata item holding the observation's footprint (m), so readers can recompute its pixels.
inline constexpr const char* kFootprintItem = "STRATA_SAMPLE_FOOTPRINT";

// Writes `observation` of `planet` into `directory` as tiled, DEFLATE-compressed GeoTIFFs. Each pixel
// centre goes through PROJ's inverse to longitude/latitude, where the model is evaluated. Rows are made in
// blocks on every core and written as they finish, so memory stays a few blocks however large the raster.
// `progress`: report the share done on stdout. Throws std::runtime_error naming the file on failure.
void writeObservation(const Observation& observation, const procedural::PlanetModel& planet,
                      const std::filesystem::path& directory, Products products, bool progress);

}  // namespace strata::testdata
