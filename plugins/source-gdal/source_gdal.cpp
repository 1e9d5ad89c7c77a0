// source.gdal: a layer from any raster GDAL opens, in any registered projection, of any size: its texels
// reach the GPU page by page through the engine's page cache. A vector file's polygons become a mask
// raster first (polygon_mask.hpp), served like any other.
#include <gdal_priv.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <strata/log.hpp>
#include <strata/plugin/paged_raster_layer.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "band_choice.hpp"
#include "body_of_the_crs.hpp"
#include "colour_encoding.hpp"
#include "gdal_page_source.hpp"
#include "georeferencing.hpp"
#include "healpix_page_source.hpp"
#include "healpix_pyramid_file.hpp"
#include "object_space_normals.hpp"
#include "polygon_mask.hpp"
#include "quiet_gdal_errors.hpp"
#include "raster_reading.hpp"
#include "source_gdal_settings.hpp"
#include "value_range.hpp"

namespace strata::gdal {
namespace {

class GdalSource : public Node {
 public:
  explicit GdalSource(const NodeSetup& setup)
      : parameters_(setup.parameters),
        settings_(gdalParameters().read(setup.parameters)),
        plugins_(*setup.plugins),
        body_(*setup.body),
        encoding_(colourEncodingOf(setup, settings_)),
        layer_(setup.id, settings_.kind),
        objectSpaceNormals_(layer_, setup.id) {
    layer_.setValueTransform(settings_.scale, settings_.offset);
    if (settings_.objectSpace && settings_.greenSouth)
      throw Error(whereOf(&GdalSettings::greenSouth),
                  "normal_green: south is a tangent-space map's convention; an object-space map's green is the "
                  "planet-fixed y axis",
                  "leave out normal_green, or set normal_space: tangent");
  }

  void open() override {
    const SourceLocation where = whereOf(&GdalSettings::path);
    std::unique_ptr<GDALDataset> file = openDataset(where);
    checkRaster(*file, settings_.kind, where);
    ChosenBand chosen = chooseBand(std::move(file), {settings_.kind, settings_.band, whereOf(&GdalSettings::kind),
                                                     whereOf(&GdalSettings::band), settings_.greenSouth});
    std::unique_ptr<GDALDataset> dataset = std::move(chosen.dataset);
    if (chosen.file) memoryFile_ = std::move(chosen.file);
    reportAnotherBody(*dataset, settings_.projection, body_, where);
    std::optional<HealpixPyramidFile> healpix = healpixPyramidOf(*dataset, plugins_, where);
    if (pageFormatOf(settings_.kind) == PageFormat::Values)
      countValues(*dataset, healpix ? healpix->ranges.get() : nullptr);
    if (settings_.kind == LayerKind::Height) refuseHeightsNoTerrainHas(where);
    if (healpix) {
      refusePlacement("a HEALPix pyramid");
      georeference_ = std::move(healpix->georeference);
      layer_.setPageRanges(std::move(healpix->ranges));
      // A window lies inside one face, so its pages need no border from another.
      if (healpix->window)
        source_ = std::make_shared<GdalPageSource>(std::move(dataset), settings_.kind, encoding_);
      else
        source_ = std::make_shared<HealpixPageSource>(std::move(dataset), settings_.kind, encoding_, healpix->nside);
      return;
    }
    georeference_ = georeferenceOf(*dataset, plugins_,
                                   {settings_.projection, whereOf(&GdalSettings::projection), settings_.extent,
                                    whereOf(&GdalSettings::extent), where});
    warnWithoutOverviews(*dataset);
    source_ = std::make_shared<GdalPageSource>(std::move(dataset), settings_.kind, encoding_, memoryFile_);
  }

  void createResources(GpuContext& gpu) override { layer_.attach(*gpu.pages, source_, georeference_); }

  // Sampled from each point's offset to the point below the eye, so that centimetre texels stay exact
  // anywhere on the body (ProjectedRasterLayer::setReference).
  void prepare(const FrameState& frame) override { layer_.setReference(frame.view.reference); }

  Layer* layer() override {
    if (settings_.kind == LayerKind::Normal && settings_.objectSpace) return &objectSpaceNormals_;
    return &layer_;
  }

 private:
  // Where the pipeline gives the setting held in `member` (the node's location for a default).
  template <class T>
  const SourceLocation& whereOf(T GdalSettings::*member) const {
    return gdalParameters().where(parameters_, member);
  }

  // The raster at `path`, or the mask of its polygons where GDAL opens it only as a vector file.
  std::unique_ptr<GDALDataset> openDataset(const SourceLocation& where) {
    const std::string path = settings_.path.string();
    if (std::error_code error; std::filesystem::file_size(path, error) == 0 && !error)
      throw Error(where, "'" + path + "' is empty (0 bytes)", "the file was not written out: copy or make it again");
    std::string rasterError;
    {
      const QuietGdalErrors quiet;  // a vector file is no raster: not worth a message of GDAL's own
      CPLErrorReset();
      std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
      if (dataset) return dataset;
      rasterError = CPLGetLastErrorMsg();
    }
    std::unique_ptr<GDALDataset> vector(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    if (!vector)
      throw Error(where, "GDAL cannot open '" + path + "' as a raster or a vector file: " + rasterError,
                  "check the path, and that `gdalinfo " + path + "` or `ogrinfo " + path + "` reads it");
    return polygonMaskOf(*vector, where);
  }

  std::unique_ptr<GDALDataset> polygonMaskOf(GDALDataset& vector, const SourceLocation& where) {
    const std::string path = vector.GetDescription();
    if (settings_.kind != LayerKind::Mask)
      throw Error(whereOf(&GdalSettings::kind),
                  "'" + path + "' is a vector file, which source.gdal reads as a mask of its polygons",
                  "add `kind: mask`, and give the layer as a `mask` (composite.overlay_mask)");
    if (!settings_.extent.empty())
      throw Error(whereOf(&GdalSettings::extent), "'" + path + "' is a vector file, whose polygons say where they lie",
                  "remove `extent`");
    PolygonMask mask = rasterisePolygons(vector, {settings_.vectorLayer, whereOf(&GdalSettings::vectorLayer),
                                                  settings_.texels, !settings_.projection.empty(), where});
    memoryFile_ = std::move(mask.file);
    return std::move(mask.raster);
  }

  // The range of a one-channel raster's values, and a height raster's block by block, which patches of
  // terrain take their own heights from (RegionalValueLayer::valuesWithin); the ranges `strata tile` stored (a HEALPix
  // pyramid's pages', a large raster's blocks) need no reading.
  void countValues(GDALDataset& dataset, const healpix::PageRanges* pageRanges) {
    const std::shared_ptr<BlockRanges> blocks =
        settings_.kind == LayerKind::Height && !pageRanges ? blockRangesOf(dataset) : nullptr;
    const std::optional<ValueRange> raw = blocks ? exactRawRange(dataset, *blocks) : exactRawRange(dataset, pageRanges);
    if (raw) layer_.setRawRange(*raw);
    layer_.setBlockRanges(blocks);
  }

  // A file that places itself (a HEALPix pyramid) takes no `projection` or `extent`.
  void refusePlacement(const std::string& what) const {
    const bool projection = !settings_.projection.empty(), extent = !settings_.extent.empty();
    if (!projection && !extent) return;
    const std::string name = projection ? "projection" : "extent";
    throw Error(projection ? whereOf(&GdalSettings::projection) : whereOf(&GdalSettings::extent),
                "'" + settings_.path.string() + "' is " + what + ", which says where its texels lie",
                "remove `" + name + "`");
  }

  // Heights beyond any body's relief are a fill value the file does not declare as nodata, or not metres;
  // drawn, they would be spikes to the stars, and the generator's height range would have to take them in.
  void refuseHeightsNoTerrainHas(const SourceLocation& where) const {
    const std::optional<ValueRange> range = layer_.valueRange();
    if (!range || (range->least >= -kMostRelief && range->greatest <= kMostRelief)) return;
    std::array<char, 96> extremes{};
    std::snprintf(extremes.data(), extremes.size(), "%g to %g m", range->least, range->greatest);
    const std::string path = settings_.path.string();
    throw Error(where,
                "'" + path + "' holds heights from " + extremes.data() +
                    " (after scale and offset), beyond any terrain: a fill value not declared as nodata, or not metres",
                "declare the fill value: gdal_edit.py -a_nodata VALUE " + path +
                    ", or convert to metres with `scale` and `offset`");
  }

  // 1000 km: far above the relief mapped on any body, tens of kilometres (Mars' 30 km, Vesta's about 40),
  // yet far below the fill values files use (-3.4e38, -1e20, 9.97e36).
  static constexpr double kMostRelief = 1.0e6;

  // Coarse pages of a large raster without overviews are averaged from every texel under them: slow.
  static void warnWithoutOverviews(GDALDataset& dataset) {
    const int longest = std::max(dataset.GetRasterXSize(), dataset.GetRasterYSize());
    if (longest <= kSlowWithoutOverviews || dataset.GetRasterBand(1)->GetOverviewCount() > 0) return;
    const std::string file = dataset.GetDescription();
    logWarning("'" + file + "' (" + std::to_string(dataset.GetRasterXSize()) + "x" +
                   std::to_string(dataset.GetRasterYSize()) +
                   ") has no overviews, so its coarse pages are averaged from full resolution, slowly",
               "`strata tile " + file + " OUTPUT.tif` writes it as a tiled pyramid");
  }

  // 4096 texels a side: a coarse page of such a raster averages 64 full-resolution pages, under a
  // second's work; beyond, loading a view's first pages takes noticeably long.
  static constexpr int kSlowWithoutOverviews = 4096;

  ParameterSet parameters_;  // where each setting was given, for messages
  GdalSettings settings_;
  const PluginRegistry& plugins_;
  Body body_;                               // the pipeline's, which the raster's CRS is checked against
  std::optional<ColourEncoding> encoding_;  // none: values, or colours already scene-linear
  PagedRasterLayer layer_;
  ObjectSpaceNormals objectSpaceNormals_;  // layer_ seen in tangent space, where normal_space: object
  // The in-memory file the raster is read from, where it was made here: a vector file's polygons rasterised,
  // or one band of a multi-band file (ChosenBand).
  std::shared_ptr<const MemoryFile> memoryFile_;
  std::shared_ptr<GdalPageSource> source_;
  RasterGeoreference georeference_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "source.gdal";
  type.category = NodeCategory::Source;
  type.summary =
      "A layer from any raster GDAL opens (GeoTIFF, JPEG, PNG, GTX, ...), in any registered projection, "
      "or a mask from the polygons of any vector file it opens (GeoJSON, Shapefile, GeoPackage, ...)";
  type.output = PortType::Layer;
  type.parameters = gdalParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<GdalSource>(setup); };
  return type;
}

// GDAL's block cache defaults to 5% of RAM (6 GB on a 128 GB machine), which would put process memory far
// beyond any page budget. Pages are read once and then held on the GPU, so GDAL only needs the few tiles
// the pages being read straddle. A GDAL_CACHEMAX the user set is kept.
constexpr GIntBig kBlockCacheBytes = 64 << 20;

void registerTypes(PluginRegistrar& registrar) {
  GDALAllRegister();  // once, here: it is not safe to call while sources open on several workers
  if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(kBlockCacheBytes);
  registrar.add(declaration());
}

}  // namespace
}  // namespace strata::gdal

STRATA_PLUGIN("source-gdal", "0.1.0", strata::gdal::registerTypes)
