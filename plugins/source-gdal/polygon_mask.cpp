#include "polygon_mask.hpp"

#include <gdal_alg.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <vector>

#include <strata/plugin/page_pyramid.hpp>

namespace strata::gdal {
namespace {

std::string describe(GDALDataset& dataset) { return dataset.GetDescription(); }

OGRLayer& layerOf(GDALDataset& vector, const PolygonMaskOptions& options) {
  if (vector.GetLayerCount() < 1)
    throw Error(options.fileWhere, "'" + describe(vector) + "' holds neither raster bands nor vector layers",
                "point `path` at a raster, or at a vector file of polygons (`ogrinfo FILE` lists its layers)");
  if (options.layer.empty()) return *vector.GetLayer(0);
  if (OGRLayer* layer = vector.GetLayerByName(options.layer.c_str())) return *layer;
  std::string names;
  for (OGRLayer* layer : vector.GetLayers()) names += (names.empty() ? "" : ", ") + std::string(layer->GetName());
  throw Error(options.layerWhere, "'" + describe(vector) + "' has no layer '" + options.layer + "'; it has " + names,
              "name one of them in `vector_layer`, or leave `vector_layer` out for the first");
}

bool isPolygonal(OGRwkbGeometryType type) {
  const OGRwkbGeometryType flat = wkbFlatten(type);
  return OGR_GT_IsSubClassOf(flat, wkbCurvePolygon) || OGR_GT_IsSubClassOf(flat, wkbMultiSurface);
}

struct Polygons {
  std::vector<std::unique_ptr<OGRGeometry>> geometries;
  OGREnvelope extent;
};

// The layer's polygons and multipolygons; points and lines bound no area, so they are left out.
Polygons polygonsOf(OGRLayer& layer) {
  Polygons polygons;
  layer.ResetReading();
  for (const auto& feature : layer) {
    const OGRGeometry* geometry = feature->GetGeometryRef();
    if (!geometry || geometry->IsEmpty() || !isPolygonal(geometry->getGeometryType())) continue;
    OGREnvelope envelope;
    geometry->getEnvelope(&envelope);
    polygons.extent.Merge(envelope);
    polygons.geometries.emplace_back(geometry->clone());
  }
  return polygons;
}

// Texels of 0 round the polygons' extent, so that every edge of a polygon lies inside the raster and is
// filtered as an edge of its values. A feather (composite.overlay_mask) averages the mask over up to a texel
// of its coarsest level, the first of one page (512 texels): up to 1/256 of its extent, which near the
// raster's own edge, beyond which it has no coverage, would average that edge too and not the polygon's.
// texels / 64 is some 4 such texels; 2 more for the bilinear filter of the finest.
int marginOf(int texels) { return texels / 64 + 2; }

struct Grid {
  std::array<double, 6> geotransform{};
  int width = 0;
  int height = 0;
};

// Square texels, `texels` of them across the extent's longer side, plus the margin.
Grid gridOver(const OGREnvelope& extent, int texels) {
  const double spanX = extent.MaxX - extent.MinX, spanY = extent.MaxY - extent.MinY;
  const double size = std::max(spanX, spanY) / texels;
  const int margin = marginOf(texels);
  return {{extent.MinX - margin * size, size, 0.0, extent.MaxY + margin * size, 0.0, -size},
          int(std::ceil(spanX / size)) + 2 * margin,
          int(std::ceil(spanY / size)) + 2 * margin};
}

void burn(GDALDataset& raster, const Polygons& polygons, const SourceLocation& where, const std::string& file) {
  std::vector<OGRGeometryH> handles;
  for (const auto& geometry : polygons.geometries) handles.push_back(OGRGeometry::ToHandle(geometry.get()));
  const std::vector<double> inside(handles.size(), 1.0);
  int band = 1;
  CPLErrorReset();
  if (GDALRasterizeGeometries(GDALDataset::ToHandle(&raster), 1, &band, int(handles.size()), handles.data(), nullptr,
                              nullptr, inside.data(), nullptr, nullptr, nullptr) != CE_None)
    throw Error(where, "GDAL cannot rasterise the polygons of '" + file + "': " + CPLGetLastErrorMsg(),
                "check them with `ogrinfo -al " + file + "`");
}

// A tiled GeoTIFF in memory: pages are read from it as windows, as from any raster file. Float32, since GDAL
// averages a band in its own type: 0/1 Bytes would round the overviews' edge texels to 0 or 1 and shift
// their edges by up to half a texel, which a feather across them would show.
std::unique_ptr<GDALDataset> createRaster(const std::string& path, const Grid& grid, const SourceLocation& where,
                                          const std::string& file) {
  CPLStringList options;
  options.SetNameValue("TILED", "YES");
  CPLErrorReset();
  std::unique_ptr<GDALDataset> raster(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      path.c_str(), grid.width, grid.height, 1, GDT_Float32, options.List()));
  if (!raster)
    throw Error(where,
                "GDAL cannot make the " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                    " mask of '" + file + "': " + CPLGetLastErrorMsg(),
                "give fewer `texels`");
  raster->SetGeoTransform(const_cast<double*>(grid.geotransform.data()));
  return raster;
}

// Averaged overviews down to one page, as `strata tile` writes them, so that coarse pages are read from them
// rather than averaged from every texel (which a raster of more than 4096 texels is warned of).
void buildOverviews(GDALDataset& raster, const SourceLocation& where, const std::string& file) {
  std::vector<int> factors;
  for (int factor = 2; std::max(raster.GetRasterXSize(), raster.GetRasterYSize()) / (factor / 2) > kPagePayload;
       factor *= 2)
    factors.push_back(factor);
  CPLErrorReset();
  if (raster.BuildOverviews("AVERAGE", int(factors.size()), factors.data(), 0, nullptr, nullptr, nullptr) != CE_None)
    throw Error(where, "GDAL cannot average the mask of '" + file + "' into overviews: " + CPLGetLastErrorMsg(),
                "give fewer `texels`");
}

}  // namespace

PolygonMask rasterisePolygons(GDALDataset& vector, const PolygonMaskOptions& options) {
  const std::string file = describe(vector);
  OGRLayer& layer = layerOf(vector, options);
  const std::string named = "'" + file + "' layer '" + layer.GetName() + "'";
  if (!layer.GetSpatialRef() && !options.crsGiven)
    throw Error(options.fileWhere, named + " has no CRS, so where its polygons lie is unknown",
                "give `projection:` (a PROJ string or EPSG:code), or assign one: "
                "ogr2ogr -a_srs EPSG:4326 out.gpkg " +
                    file);
  const Polygons polygons = polygonsOf(layer);
  if (polygons.geometries.empty() || !(polygons.extent.MaxX > polygons.extent.MinX) ||
      !(polygons.extent.MaxY > polygons.extent.MinY))
    throw Error(options.fileWhere, named + " holds no polygons, so it bounds no area to mask",
                "point `path` (or `vector_layer`) at polygons or multipolygons (`ogrinfo -al -so " + file + "`)");
  static std::atomic<unsigned> made{0};
  PolygonMask mask{std::make_shared<const MemoryFile>("/vsimem/strata-polygon-mask-" + std::to_string(made++) + ".tif"),
                   nullptr};
  {
    std::unique_ptr<GDALDataset> raster =
        createRaster(mask.file->path(), gridOver(polygons.extent, options.texels), options.fileWhere, file);
    if (const OGRSpatialReference* crs = layer.GetSpatialRef()) raster->SetSpatialRef(crs);
    burn(*raster, polygons, options.fileWhere, file);
    buildOverviews(*raster, options.fileWhere, file);
  }  // closed: written out
  mask.raster.reset(GDALDataset::Open(mask.file->path().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!mask.raster)
    throw Error(options.fileWhere, "GDAL cannot read back the mask of " + named + ": " + CPLGetLastErrorMsg(),
                "give fewer `texels`");
  return mask;
}

}  // namespace strata::gdal
