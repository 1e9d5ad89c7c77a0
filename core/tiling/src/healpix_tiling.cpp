// The HEALPix pyramid (strata/plugin/healpix_pyramid.hpp) written with GDAL's warper. Each base face is a square
// grid turned by 45 degrees in the planar HEALPix projection (Calabretta & Roukema 2007) centred on the
// meridian of its column of faces, which a rotated geotransform describes exactly; so warping the input into
// that grid gives each face texel the input's bilinear value at its pixel's centre.
#include "healpix_tiling.hpp"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <numbers>
#include <optional>
#include <vector>

#include <strata/crs.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

#include "block_range_scan.hpp"
#include "cog_writing.hpp"
#include "face_window.hpp"
#include "globe_wrapping.hpp"
#include "page_range_scan.hpp"
#include "projection/projection_terms.hpp"
#include "tile_target.hpp"

namespace strata::tiling {
namespace {

constexpr std::int64_t kChunkTexels = std::int64_t{64} << 20;  // what one warp holds in memory, at most
constexpr int kStripTile = 512;                                // the temporary strip's tiles, as the COG's
constexpr double kFacesShare = 0.6;                            // of the progress; the COG has the rest

// How the output marks texels the input does not cover so that the page cache reads them as coverage 0:
// source.gdal takes coverage from band 1's mask band (its nodata, or the alpha band) and from NaN values.
struct Samples {
  GDALDataType type = GDT_Unknown;
  int bands = 0;               // of the output, an alpha band included
  bool alpha = false;          // the last band is alpha: the input's, or one added to three colour bands
  bool rgb = false;            // bands 1 to 3 are red, green and blue
  std::vector<double> nodata;  // per band, or empty
};

struct Pyramid {
  std::int64_t nside = 0;
  std::string figure;   // "+proj=healpix" and the input's ellipsoid
  double radius = 0.0;  // of the plane, in metres
  // Face texels per input texel: the resampling factor of the warper's kernel. GDAL would take it from
  // each face's window in the input, which a face holding a pole or the antimeridian stretches to the
  // input's whole width, widening the bilinear kernel as if it were reducing the input.
  double scale = 1.0;
  Samples samples;
};

// A part of one face that the warper fills, in level-0 face texels, and where its first texel lies in the
// file written: a face of the strip (fileColumn = face nside), or a windowed pyramid's whole file.
struct FaceArea {
  healpix::FaceWindow texels;
  std::int64_t fileColumn = 0;
};

// What the file holds: the twelve faces side by side, or, finer than the strip allows, a window of one face.
std::vector<FaceArea> areasOf(const Pyramid& pyramid, const std::optional<healpix::FaceWindow>& window) {
  if (window) return {{*window, 0}};
  std::vector<FaceArea> faces;
  const int side = int(pyramid.nside);
  for (int face = 0; face < 12; ++face) faces.push_back({{face, 0, 0, side, side}, face * pyramid.nside});
  return faces;
}

// A face is a twelfth of the sphere, R sqrt(pi / 3) across.
double faceTexelMetres(double radius, std::int64_t nside) {
  return radius * std::sqrt(std::numbers::pi / 3.0) / double(nside);
}

// Each band's nodata (band 1's where a band declares none), or none when band 1 declares none.
std::vector<double> declaredNodata(GDALDataset& input) {
  int declared = 0;
  const double first = input.GetRasterBand(1)->GetNoDataValue(&declared);
  std::vector<double> nodata;
  for (int band = 1; declared && band <= input.GetRasterCount(); ++band) {
    int own = 0;
    const double value = input.GetRasterBand(band)->GetNoDataValue(&own);
    nodata.push_back(own ? value : first);
  }
  return nodata;
}

// The input's alpha band, or else its nodata, where it has them; otherwise NaN for floats, an added alpha
// band for three colour bands (any value of them may be a real colour), and for other integers the least
// value of a signed type (as -32768 for heights) or the greatest of an unsigned one (0 is as often real).
Samples samplesOf(GDALDataset& input) {
  Samples samples;
  GDALRasterBand& first = *input.GetRasterBand(1);
  samples.type = first.GetRasterDataType();
  samples.bands = input.GetRasterCount();
  samples.rgb = samples.bands >= 3 && first.GetColorInterpretation() == GCI_RedBand;
  samples.alpha = input.GetRasterBand(samples.bands)->GetColorInterpretation() == GCI_AlphaBand;
  if (samples.alpha) return samples;  // the warper reads the input's nodata too, and writes alpha 0 for it
  samples.nodata = declaredNodata(input);
  if (!samples.nodata.empty()) return samples;
  if (GDALDataTypeIsFloating(samples.type)) {
    samples.nodata.assign(std::size_t(samples.bands), std::nan(""));
  } else if (samples.bands == 3) {
    samples.bands = 4;
    samples.alpha = true;
  } else {
    const double extreme = GDALDataTypeIsSigned(samples.type) ? -HUGE_VAL : HUGE_VAL;
    samples.nodata.assign(std::size_t(samples.bands),
                          GDALAdjustValueToDataType(samples.type, extreme, nullptr, nullptr));
  }
  return samples;
}

std::int64_t checkedNside(std::int64_t nside) {
  std::string problem;
  if (!std::has_single_bit(std::uint64_t(nside)))
    problem = "is not a power of two";
  else if (nside < healpix::kLeastNside)
    problem = "is below " + std::to_string(healpix::kLeastNside) + ", the least: a face must fill a whole page";
  else if (nside > healpix::kMostWindowedNside)
    problem = "is above 2^30, the most: a window of one face counts its texels in 32 bits";
  if (problem.empty()) return nside;
  throw Error({"--nside"}, "nside " + std::to_string(nside) + " " + problem,
              "give a power of two from " + std::to_string(healpix::kLeastNside) +
                  " (e.g. 1024 or 4096) to 2^30, or leave --nside out to match the input's texels");
}

// The haversine distance (m) between places i and j of x (longitudes) and y (latitudes), in degrees, on a
// sphere of `radius`.
double greatCircle(const double x[], const double y[], int i, int j, double radius) {
  const double dLat = (y[j] - y[i]) * kDegree, dLon = (x[j] - x[i]) * kDegree;
  const double h = std::pow(std::sin(dLat / 2.0), 2.0) +
                   std::cos(y[i] * kDegree) * std::cos(y[j] * kDegree) * std::pow(std::sin(dLon / 2.0), 2.0);
  return 2.0 * radius * std::asin(std::sqrt(std::min(h, 1.0)));
}

// The shorter side (m) of the input's centre texel, on the sphere of its semi-major axis: the resolution
// the pyramid must keep where the input is likely to be typical.
double centreTexelMetres(GDALDataset& input, const SourceLocation& where) {
  std::array<double, 6> t{};
  input.GetGeoTransform(t.data());
  const double column = double(input.GetRasterXSize() / 2) + 0.5, row = double(input.GetRasterYSize() / 2) + 0.5;
  double x[3], y[3];  // the centre texel's centre, one column and one row on
  for (int i = 0; i < 3; ++i) {
    const double c = column + (i == 1), r = row + (i == 2);
    x[i] = t[0] + c * t[1] + r * t[2];
    y[i] = t[3] + c * t[4] + r * t[5];
  }
  const Transformation toGeographic = geographicTransformation(*input.GetSpatialRef());
  if (!toGeographic || !toGeographic->Transform(3, x, y))
    throw Error(where, "PROJ cannot place the centre of '" + std::string(input.GetDescription()) + "' on the body",
                "check its CRS and geotransform: gdalinfo " + std::string(input.GetDescription()));
  const double radius = input.GetSpatialRef()->GetSemiMajor();
  return std::min(greatCircle(x, y, 0, 1, radius), greatCircle(x, y, 0, 2, radius));
}

// The least nside whose face texels are no larger than `inputTexel` (m).
std::int64_t automaticNside(double inputTexel, double radius, const SourceLocation& where) {
  std::int64_t nside = healpix::kLeastNside;
  while (faceTexelMetres(radius, nside) > inputTexel && nside < healpix::kMostWindowedNside) nside *= 2;
  if (faceTexelMetres(radius, nside) > inputTexel)
    throw Error(where, "its texels (" + std::to_string(inputTexel) + " m) are finer than the finest HEALPix pyramid's",
                "choose a coarser resolution: --nside N, a power of two up to 2^30");
  return nside;
}

// The texels of one warp: `rows` rows of a face, band after band.
struct Chunk {
  int rows = 0;
  std::vector<std::byte> texels;
};

// Rows of an area of about kChunkTexels texels together, whole rows of strip tiles where they fit, so that
// no compressed tile of the strip is written twice.
Chunk chunkFor(const Pyramid& pyramid, const healpix::FaceWindow& area) {
  const std::int64_t rows = std::clamp<std::int64_t>(kChunkTexels / area.width, 1, area.height);
  const std::int64_t whole = rows >= kStripTile ? rows / kStripTile * kStripTile : rows;
  const std::size_t bytes = std::size_t(whole * area.width) * std::size_t(pyramid.samples.bands) *
                            std::size_t(GDALGetDataTypeSizeBytes(pyramid.samples.type));
  return {int(whole), std::vector<std::byte>(bytes)};
}

void markMissing(GDALDataset& dataset, const Samples& samples) {
  for (std::size_t band = 0; band < samples.nodata.size(); ++band)
    dataset.GetRasterBand(int(band) + 1)->SetNoDataValue(samples.nodata[band]);
  if (samples.alpha) dataset.GetRasterBand(samples.bands)->SetColorInterpretation(GCI_AlphaBand);
}

// The value of a band's texels that the input does not cover: its nodata, or 0 (alpha 0) without.
double missingValue(const Samples& samples, int band) {
  return samples.nodata.empty() ? 0.0 : samples.nodata[std::size_t(band)];
}

// Every texel of `chunk` "not covered", before a warp: GDAL's warper skips the parts of a window that no
// input texel reaches (SKIP_NOSOURCE, which saves most of the work for a regional input) without
// initialising them.
void clearChunk(Chunk& chunk, std::size_t texels, const Samples& samples) {
  const std::size_t size = std::size_t(GDALGetDataTypeSizeBytes(samples.type));
  for (int band = 0; band < samples.bands; ++band) {
    const double missing = missingValue(samples, band);
    GDALCopyWords64(&missing, GDT_Float64, 0, chunk.texels.data() + std::size_t(band) * texels * size, samples.type,
                    int(size), GPtrDiff_t(texels));
  }
}

// A MEM dataset over `chunk`'s texels for rows [row, row + rows) of `area`, in the plane centred on the
// face's meridian where the face lies whole.
Dataset areaWindow(const Pyramid& pyramid, const healpix::FaceWindow& area, int row, int rows, Chunk& chunk) {
  const int width = area.width;
  Dataset window(
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", width, rows, 0, pyramid.samples.type, nullptr));
  const std::size_t bandBytes =
      std::size_t(width) * std::size_t(rows) * std::size_t(GDALGetDataTypeSizeBytes(pyramid.samples.type));
  for (int band = 0; band < pyramid.samples.bands; ++band) {
    char pointer[64] = {};
    CPLPrintPointer(pointer, chunk.texels.data() + band * bandBytes, sizeof(pointer) - 1);
    CPLStringList options;
    options.SetNameValue("DATAPOINTER", pointer);
    window->AddBand(pyramid.samples.type, options.List());
  }
  markMissing(*window, pyramid.samples);
  OGRSpatialReference plane;
  plane.SetFromUserInput((pyramid.figure + term("lon_0", healpix::faceCentralMeridian(area.face))).c_str());
  window->SetSpatialRef(&plane);
  std::array<double, 6> t = healpix::facePlaneGeotransform(area.face, pyramid.nside, pyramid.radius);
  const double column = double(area.column), first = double(area.row + row);  // the window's first texel's
  t[0] += column * t[1] + first * t[2];
  t[3] += column * t[4] + first * t[5];
  window->SetGeoTransform(t.data());
  return window;
}

void warp(GDALDataset& input, GDALDataset& window, const Pyramid& pyramid, const SourceLocation& where) {
  const Samples& samples = pyramid.samples;
  const std::string scale = CPLSPrintf("%.17g", pyramid.scale);
  // Every texel is projected exactly (-et 0): GDAL's approximation, linear between projected texels, left
  // errors many times bilinear interpolation's own on the smooth field of tile_command_test.cpp, even at a
  // threshold of 1/100 texel. Exact projection takes about three times as long.
  std::vector<std::string> arguments{"-r", "bilinear", "-wo", "XSCALE=" + scale, "-wo", "YSCALE=" + scale, "-et", "0"};
  if (samples.alpha) arguments.push_back("-dstalpha");
  if (!samples.nodata.empty()) {
    std::string values;
    for (const double value : samples.nodata)
      values += (values.empty() ? "" : " ") + std::string(CPLSPrintf("%.17g", value));
    arguments.insert(arguments.end(), {"-dstnodata", values});
  }
  std::unique_ptr<GDALWarpAppOptions, void (*)(GDALWarpAppOptions*)> options(
      GDALWarpAppOptionsNew(argvOf(arguments).data(), nullptr), GDALWarpAppOptionsFree);
  GDALDatasetH source = GDALDataset::ToHandle(&input);
  const AllCpusForWarping threads;
  // To bound the part of the input it reads, the warper also projects a grid of input texels forwards; the
  // rows that wrapAroundGlobe adds past the poles fail there, harmlessly, each with a message. What makes
  // the warp fail is reported below, with GDAL's last message.
  const CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  CPLErrorReset();
  if (!GDALWarp(nullptr, GDALDataset::ToHandle(&window), 1, &source, options.get(), nullptr))
    throw Error(where, "GDAL's warper failed on a face of the HEALPix pyramid: " + std::string(CPLGetLastErrorMsg()),
                "check that `gdalinfo` reads the input, and that PROJ knows its CRS");
}

// The file the faces are warped into: the strip of twelve faces, or a window of one.
Dataset createFaces(const std::filesystem::path& file, const Pyramid& pyramid,
                    const std::optional<healpix::FaceWindow>& window, const SourceLocation& where) {
  CPLStringList options;
  for (const char* option : {"TILED=YES", "COMPRESS=DEFLATE", "ZLEVEL=1", "BIGTIFF=YES", "SPARSE_OK=TRUE"})
    options.AddString(option);
  options.SetNameValue("BLOCKXSIZE", std::to_string(kStripTile).c_str());
  options.SetNameValue("BLOCKYSIZE", std::to_string(kStripTile).c_str());
  if (pyramid.samples.alpha) options.SetNameValue("ALPHA", "YES");
  if (pyramid.samples.rgb) options.SetNameValue("PHOTOMETRIC", "RGB");
  CPLErrorReset();
  const int width = window ? window->width : int(12 * pyramid.nside),
            height = window ? window->height : int(pyramid.nside);
  Dataset strip(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      file.c_str(), width, height, pyramid.samples.bands, pyramid.samples.type, options.List()));
  if (!strip)
    throw Error(where, "GDAL could not create the temporary '" + file.string() + "': " + CPLGetLastErrorMsg(),
                "check that the output's folder is writable and that the disk has room");
  markMissing(*strip, pyramid.samples);
  std::array<double, 6> geotransform =
      window ? healpix::windowGeotransform(pyramid.nside, *window) : healpix::stripGeotransform(pyramid.nside);
  strip->SetGeoTransform(geotransform.data());
  if (window) strip->SetMetadataItem(healpix::kWindowItem, healpix::windowItem(*window).c_str());
  strip->SetMetadataItem(healpix::kNsideItem, std::to_string(pyramid.nside).c_str());
  strip->SetMetadataItem(healpix::kFigureItem, pyramid.figure.c_str());
  strip->SetMetadataItem(healpix::kOrderingItem, "NESTED");
  return strip;
}

// Whether the warp reached any texel of the window `chunk` holds: whether its coverage band (the alpha band,
// else band 1) holds anything but "missing".
bool reached(const Chunk& chunk, std::size_t texels, const Samples& samples) {
  const std::size_t size = std::size_t(GDALGetDataTypeSizeBytes(samples.type));
  const int coverage = samples.alpha ? samples.bands - 1 : 0;
  const double missingTexel = missingValue(samples, coverage);
  std::vector<std::byte> missing(size);
  GDALCopyWords64(&missingTexel, GDT_Float64, 0, missing.data(), samples.type, 0, 1);
  const std::byte* band = chunk.texels.data() + std::size_t(coverage) * texels * size;
  for (std::size_t texel = 0; texel < texels; ++texel)
    if (std::memcmp(band + texel * size, missing.data(), size) != 0) return true;
  return false;
}

void writeAreas(GDALDataset& input, GDALDataset& file, const Pyramid& pyramid, const std::vector<FaceArea>& areas,
                const std::function<void(double)>& progress, const SourceLocation& where) {
  double total = 0.0, done = 0.0;
  for (const FaceArea& area : areas) total += double(area.texels.width) * area.texels.height;
  for (const FaceArea& area : areas) {
    const healpix::FaceWindow& texels = area.texels;
    Chunk chunk = chunkFor(pyramid, texels);
    for (int row = 0; row < texels.height; row += chunk.rows) {
      const int rows = std::min(chunk.rows, texels.height - row);
      const std::size_t count = std::size_t(texels.width) * std::size_t(rows);
      clearChunk(chunk, count, pyramid.samples);
      warp(input, *areaWindow(pyramid, texels, row, rows, chunk), pyramid, where);
      CPLErrorReset();
      // The strip is sparse: what is not written reads as missing, which spares compressing and writing the
      // empty faces of an input that covers a small part of the sphere.
      if (reached(chunk, count, pyramid.samples) &&
          file.RasterIO(GF_Write, int(area.fileColumn), row, texels.width, rows, chunk.texels.data(), texels.width,
                        rows, pyramid.samples.type, pyramid.samples.bands, nullptr, 0, 0, 0, nullptr) != CE_None)
        throw Error(
            where,
            "GDAL could not write the temporary '" + std::string(file.GetDescription()) + "': " + CPLGetLastErrorMsg(),
            "check that the disk has room");
      done += double(count);
      if (progress) progress(kFacesShare * done / total);
    }
  }
}

}  // namespace

TilingResult tileHealpix(const PluginRegistry& plugins, GDALDataset& input, const TilingRequest& request) {
  const SourceLocation where{request.input.string()};
  const std::string figure = "+proj=healpix" + figureTerms(*input.GetSpatialRef());
  const double radius = projectionOfCrs(plugins, figure, where)->glslMapScale();
  const double inputTexel = centreTexelMetres(input, where);
  const std::int64_t nside =
      request.nside != 0 ? checkedNside(request.nside) : automaticNside(inputTexel, radius, where);
  const Pyramid pyramid{nside, figure, radius, inputTexel / faceTexelMetres(radius, nside), samplesOf(input)};
  std::optional<healpix::FaceWindow> window;
  if (nside > healpix::kMostNside)
    window =
        faceWindowCovering(input, *healpix::stripProjection(projectionOfCrs(plugins, figure, where)), nside, where);
  // Beside the output, in the scratch folder tileRaster writes it in, which goes with everything it holds.
  Dataset faces = createFaces(request.output.parent_path() / "faces.strip.tif", pyramid, window, where);
  const Dataset wrapped = wrapAroundGlobe(input);
  writeAreas(wrapped ? *wrapped : input, *faces, pyramid, areasOf(pyramid, window), request.progress, where);
  // One-channel strips (heights, scalars) carry their pages' true ranges, which bound geometry.healpix's nodes;
  // a window is paged as any raster, and carries its blocks' ranges as any raster does.
  MetadataItems ranges;
  if (pyramid.samples.bands == 1)
    ranges = window ? blockRangeItems(*faces) : scanPageRanges(*faces, nside).metadataItems();
  Dataset output = writeCog(*faces, request.output, "", progressShare(request.progress, kFacesShare, 1.0),
                            {request.output.string()}, ranges);
  return {figure,
          true,
          output->GetRasterXSize(),
          output->GetRasterYSize(),
          output->GetRasterBand(1)->GetOverviewCount(),
          pyramid.nside};
}

}  // namespace strata::tiling
