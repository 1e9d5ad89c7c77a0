#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/port.hpp>

namespace strata::gdal {

// source.gdal's settings as a pipeline writes them, each default's reason beside it.
struct GdalSettings {
  std::filesystem::path path;  // required: the raster, or a vector file of polygons
  LayerKind kind = LayerKind::Color;
  int band = 0;                     // none: a one-channel kind reads the file's only band, and is refused several
  bool greenSouth = false;          // OpenGL's convention for normal maps: green up the image, north
  bool objectSpace = false;         // most normal maps (Stellarium's, games', baked ones) are tangent-space
  std::string colorspace = "srgb";  // 8-bit imagery (cameras, the web, map tiles) is almost always sRGB-encoded
  double scale = 1.0;
  double offset = 0.0;
  std::vector<double> extent;  // empty: from the geotransform
  std::string projection;      // empty: the file's CRS
  std::string vectorLayer;     // empty: the file's first
  // The polygons' edges within half a texel of 1/2048 of their extent, under a pixel wherever the whole mask
  // fits on a 1920-pixel screen, in 16 MB (Float32); finer edges up close want a larger value, up to 8192
  // (256 MB, held in memory while the node lives).
  int texels = 2048;
};

const ParameterBindings<GdalSettings>& gdalParameters();

}  // namespace strata::gdal
