// The HEALPix pyramid (strata/healpix_pyramid.hpp) written with GDAL's warper. Each base face is a square
// grid turned by 45 degrees in the planar HEALPix projection (Calabretta & Roukema 2007) centred on the
// meridian of its column of faces, which a rotated geotransform describes exactly; so warping the input into
// that grid gives each face texel the input's bilinear value at its pixel's centre.
#include "tiling/healpix_tiling.hpp"

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
#include <vector>

#include <strata/crs.hpp>
#include <strata/healpix_pyramid.hpp>

#include "projection/projection_terms.hpp"
#include "tiling/cog_writing.hpp"
#include "tiling/globe_wrapping.hpp"
#include "tiling/page_range_scan.hpp"
#include "tiling/tile_target.hpp"

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
  else if (nside > healpix::kMostNside)
    problem = "is above 2^26, the most: 12 nside texels across must fit GDAL's 32-bit sizes, with room to spare";
  if (problem.empty()) return nside;
  throw Error({"--nside"}, "nside " + std::to_string(nside) + " " + problem,
              "give a power of two from " + std::to_string(healpix::kLeastNside) +
                  " (e.g. 1024 or 4096), or leave --nside out to match the input's texels");
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
  while (faceTexelMetres(radius, nside) > inputTexel && nside < healpix::kMostNside) nside *= 2;
  if (faceTexelMetres(radius, nside) > inputTexel)
    throw Error(where, "its texels (" + std::to_string(inputTexel) + " m) are finer than the finest HEALPix pyramid's",
                "choose a coarser resolution: --nside N, a power of two up to 2^26");
  return nside;
}

// The texels of one warp: `rows` rows of a face, band after band.
struct Chunk {
  int rows = 0;
  std::vector<std::byte> texels;
};

// Rows of a face of about kChunkTexels texels together, whole rows of strip tiles where they fit, so that
// no compressed tile of the strip is written twice.
Chunk chunkFor(const Pyramid& pyramid) {
  const std::int64_t rows = std::clamp<std::int64_t>(kChunkTexels / pyramid.nside, 1, pyramid.nside);
  const std::int64_t whole = rows >= kStripTile ? rows / kStripTile * kStripTile : rows;
  const std::size_t bytes = std::size_t(whole * pyramid.nside) * std::size_t(pyramid.samples.bands) *
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

// A MEM dataset over `chunk`'s texels for rows [row, row + rows) of face `face`, in the plane centred on the
// face's meridian where the face lies whole.
Dataset faceWindow(const Pyramid& pyramid, int face, int row, int rows, Chunk& chunk) {
  const int side = int(pyramid.nside);
  Dataset window(
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", side, rows, 0, pyramid.samples.type, nullptr));
  const std::size_t bandBytes =
      std::size_t(side) * std::size_t(rows) * std::size_t(GDALGetDataTypeSizeBytes(pyramid.samples.type));
  for (int band = 0; band < pyramid.samples.bands; ++band) {
    char pointer[64] = {};
    CPLPrintPointer(pointer, chunk.texels.data() + band * bandBytes, sizeof(pointer) - 1);
    CPLStringList options;
    options.SetNameValue("DATAPOINTER", pointer);
    window->AddBand(pyramid.samples.type, options.List());
  }
  markMissing(*window, pyramid.samples);
  OGRSpatialReference plane;
  plane.SetFromUserInput((pyramid.figure + term("lon_0", healpix::faceCentralMeridian(face))).c_str());
  window->SetSpatialRef(&plane);
  std::array<double, 6> t = healpix::facePlaneGeotransform(face, pyramid.nside, pyramid.radius);
  t[0] += row * t[2];  // the window's first row is row `row` of the face
  t[3] += row * t[5];
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

Dataset createStrip(const std::filesystem::path& file, const Pyramid& pyramid, const SourceLocation& where) {
  CPLStringList options;
  for (const char* option : {"TILED=YES", "COMPRESS=DEFLATE", "ZLEVEL=1", "BIGTIFF=YES", "SPARSE_OK=TRUE"})
    options.AddString(option);
  options.SetNameValue("BLOCKXSIZE", std::to_string(kStripTile).c_str());
  options.SetNameValue("BLOCKYSIZE", std::to_string(kStripTile).c_str());
  if (pyramid.samples.alpha) options.SetNameValue("ALPHA", "YES");
  if (pyramid.samples.rgb) options.SetNameValue("PHOTOMETRIC", "RGB");
  CPLErrorReset();
  Dataset strip(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(file.c_str(), int(12 * pyramid.nside),
                                                                         int(pyramid.nside), pyramid.samples.bands,
                                                                         pyramid.samples.type, options.List()));
  if (!strip)
    throw Error(where, "GDAL could not create the temporary '" + file.string() + "': " + CPLGetLastErrorMsg(),
                "check that the output's folder is writable and that the disk has room");
  markMissing(*strip, pyramid.samples);
  std::array<double, 6> geotransform = healpix::stripGeotransform(pyramid.nside);
  strip->SetGeoTransform(geotransform.data());
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

void writeFaces(GDALDataset& input, GDALDataset& strip, const Pyramid& pyramid,
                const std::function<void(double)>& progress, const SourceLocation& where) {
  Chunk chunk = chunkFor(pyramid);
  const int side = int(pyramid.nside);
  for (int face = 0; face < 12; ++face)
    for (int row = 0; row < side; row += chunk.rows) {
      const int rows = std::min(chunk.rows, side - row);
      clearChunk(chunk, std::size_t(side) * std::size_t(rows), pyramid.samples);
      warp(input, *faceWindow(pyramid, face, row, rows, chunk), pyramid, where);
      CPLErrorReset();
      // The strip is sparse: what is not written reads as missing, which spares compressing and writing the
      // empty faces of an input that covers a small part of the sphere.
      if (reached(chunk, std::size_t(side) * std::size_t(rows), pyramid.samples) &&
          strip.RasterIO(GF_Write, face * side, row, side, rows, chunk.texels.data(), side, rows, pyramid.samples.type,
                         pyramid.samples.bands, nullptr, 0, 0, 0, nullptr) != CE_None)
        throw Error(
            where,
            "GDAL could not write the temporary '" + std::string(strip.GetDescription()) + "': " + CPLGetLastErrorMsg(),
            "check that the disk has room");
      if (progress) progress(kFacesShare * double(face * side + row + rows) / (12.0 * side));
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
  // Beside the output, in the scratch folder tileRaster writes it in, which goes with everything it holds.
  Dataset faces = createStrip(request.output.parent_path() / "faces.strip.tif", pyramid, where);
  const Dataset wrapped = wrapAroundGlobe(input);
  writeFaces(wrapped ? *wrapped : input, *faces, pyramid, request.progress, where);
  // One-channel pyramids (heights, scalars) carry their pages' true ranges, which bound geometry.healpix's nodes.
  if (pyramid.samples.bands == 1)
    for (const auto& [name, value] : scanPageRanges(*faces, nside).metadataItems())
      faces->SetMetadataItem(name.c_str(), value.c_str());
  std::function<void(double)> progress;
  if (request.progress)
    progress = [&](double fraction) { request.progress(kFacesShare + (1.0 - kFacesShare) * fraction); };
  Dataset output = writeCog(*faces, request.output, "", progress, {request.output.string()});
  return {figure,
          true,
          output->GetRasterXSize(),
          output->GetRasterYSize(),
          output->GetRasterBand(1)->GetOverviewCount(),
          pyramid.nside};
}

}  // namespace strata::tiling
