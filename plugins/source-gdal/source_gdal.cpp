// source.gdal: a layer from any raster GDAL opens, in any registered projection, read whole (paging
// comes with the page cache).
#include <gdal_priv.h>

#include <memory>

#include <strata/plugin.hpp>
#include <strata/plugin_registry.hpp>
#include <strata/raster_layer.hpp>

#include "georeferencing.hpp"
#include "raster_reading.hpp"

namespace strata::gdal {
namespace {

class GdalSource : public Node {
 public:
  explicit GdalSource(const NodeSetup& setup)
      : parameters_(setup.parameters), plugins_(*setup.plugins), kind_(kindOf(setup)), layer_(setup.id, kind_) {
    layer_.setValueTransform(setup.parameters.real("scale"), setup.parameters.real("offset"));
  }

  void open() override {
    const SourceLocation where = parameters_.where("path");
    const std::string path = parameters_.path("path").string();
    CPLErrorReset();
    std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!dataset)
      throw Error(where, "GDAL cannot open '" + path + "' as a raster: " + CPLGetLastErrorMsg(),
                  "check the path, and that `gdalinfo " + path + "` reads it");
    georeference_ = georeferenceOf(*dataset, plugins_,
                                   {parameters_.string("projection"), parameters_.where("projection"),
                                    parameters_.reals("extent"), parameters_.where("extent"), where});
    image_ = readRaster(*dataset, kind_, where);
    georeference_.geotransform = resampledGeotransform(georeference_.geotransform, dataset->GetRasterXSize(),
                                                       dataset->GetRasterYSize(), image_.width, image_.height);
  }

  void createResources(GpuContext&) override {
    layer_.upload(image_, georeference_);
    image_ = {};  // the texture holds it now
  }

  Layer* layer() override { return &layer_; }

 private:
  static LayerKind kindOf(const NodeSetup& setup) {
    LayerKind kind = LayerKind::Color;
    parseLayerKind(setup.parameters.string("kind"), kind);  // the declaration's choices are all valid kinds
    return kind;
  }

  ParameterSet parameters_;
  const PluginRegistry& plugins_;
  LayerKind kind_;
  RasterLayer layer_;
  RasterImage image_;
  RasterGeoreference georeference_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "source.gdal";
  type.category = NodeCategory::Source;
  type.summary = "A layer from any raster GDAL opens (GeoTIFF, JPEG, PNG, GTX, ...), in any registered projection";
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "path", .type = ParameterType::Path, .doc = "the raster file; relative to the pipeline file"},
      {.name = "kind", .type = ParameterType::Choice, .defaultValue = std::string("color"),
       .doc = "what the values are: color (8/16-bit sRGB) or one-channel height, scalar, luminance, mask",
       .choices = {"color", "height", "scalar", "luminance", "mask"}},
      {.name = "scale", .type = ParameterType::Real, .defaultValue = 1.0,
       .doc = "one-channel kinds: multiplies raw values (vertical exaggeration, or counts to metres)"},
      {.name = "offset", .type = ParameterType::Real, .defaultValue = 0.0,
       .doc = "one-channel kinds: added after scale (metres for heights)"},
      {.name = "extent", .type = ParameterType::RealList, .defaultValue = std::vector<double>{}, .minimum = -360.0,
       .maximum = 360.0, .units = "deg",
       .doc = "[west, south, east, north] of a longitude/latitude raster; empty: from its geotransform (a bare 2:1 "
              "raster is global)",
       .count = 4},
      {.name = "projection", .type = ParameterType::String, .defaultValue = std::string(),
       .doc = "the raster's CRS when the file's is missing or wrong: WKT, a PROJ string or EPSG:code; empty: the "
              "file's CRS (none: longitude/latitude)"},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<GdalSource>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) {
  GDALAllRegister();  // once, here: it is not safe to call while sources open on several workers
  registrar.add(declaration());
}

}  // namespace
}  // namespace strata::gdal

STRATA_PLUGIN("source-gdal", "0.1.0", strata::gdal::registerTypes)
