#include "source_gdal_settings.hpp"

namespace strata::gdal {

const ParameterBindings<GdalSettings>& gdalParameters() {
  using S = GdalSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .required(&S::path, {.name = "path",
                               .doc = "the raster file, or a vector file of polygons (with kind: mask); relative to "
                                      "the pipeline file"})
          .choice(&S::kind,
                  {.name = "kind",
                   .doc = "what the values are: color (8/16-bit, see colorspace); normal, a normal map (0 to full "
                          "scale for -1 to 1, see normal_space); or one-channel height, scalar, luminance, mask"},
                  {{"color", LayerKind::Color},
                   {"normal", LayerKind::Normal},
                   {"height", LayerKind::Height},
                   {"scalar", LayerKind::Scalar},
                   {"luminance", LayerKind::Luminance},
                   {"mask", LayerKind::Mask}})
          .add(&S::band, {.name = "band",
                          .minimum = 0.0,
                          .maximum = 65535.0,
                          .doc = "one-channel kinds: the band read, 1 the first; 0: the file's only band (a "
                                 "multi-band file is refused)"})
          .choice(&S::greenSouth,
                  {.name = "normal_green",
                   .doc = "normal maps: where the green channel points, north (up the image: OpenGL's convention) "
                          "or south (down it: DirectX's, and Stellarium's moon_normals.png)"},
                  {{"north", false}, {"south", true}})
          .choice(&S::objectSpace,
                  {.name = "normal_space",
                   .doc = "normal maps: tangent, each normal in the ground's east/north/up frame; object, in the "
                          "body's planet-fixed axes (red toward longitude 0 on the equator, blue north)"},
                  {{"tangent", false}, {"object", true}})
          .add(&S::colorspace,
               {.name = "colorspace",
                .doc = "color: the colour space the raster's values are encoded in, one of the pipeline's "
                       "OpenColorIO config (Strata's: srgb, gamma22, linear, raw); converted to scene-linear on the "
                       "GPU"})
          .add(&S::scale,
               {.name = "scale",
                .doc = "one-channel kinds: multiplies raw values (vertical exaggeration, or counts to metres)"})
          .add(&S::offset, {.name = "offset", .doc = "one-channel kinds: added after scale (metres for heights)"})
          .add(&S::extent, {.name = "extent",
                            .minimum = -360.0,
                            .maximum = 360.0,
                            .units = "deg",
                            .doc = "[west, south, east, north] of a longitude/latitude raster; empty: from its "
                                   "geotransform (a bare 2:1 raster is global)",
                            .count = 4})
          .add(&S::projection, {.name = "projection",
                                .doc = "the raster's CRS when the file's is missing or wrong: WKT, a PROJ string or "
                                       "EPSG:code; empty: the file's CRS (none: longitude/latitude)"})
          .add(&S::vectorLayer, {.name = "vector_layer",
                                 .doc = "vector files: the layer whose polygons make the mask; empty: the file's "
                                        "first (GeoJSON and Shapefiles have one)"})
          .add(&S::texels, {.name = "texels",
                            .minimum = 16.0,
                            .maximum = 8192.0,
                            .doc = "vector files: the mask raster's texels across the polygons' longer side (how "
                                   "sharp their edges are)"});
  return bindings;
}

}  // namespace strata::gdal
