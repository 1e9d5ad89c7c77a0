#include "band_choice.hpp"

#include <gdal_utils.h>

#include <atomic>
#include <cctype>
#include <string>
#include <vector>

namespace strata::gdal {
namespace {

bool readsThreeBands(LayerKind kind) { return kind == LayerKind::Color || kind == LayerKind::Normal; }

// The bands that hold values: all but an alpha band, which masks them.
std::size_t valueBandCount(GDALDataset& dataset) {
  std::size_t count = 0;
  for (int i = 1; i <= dataset.GetRasterCount(); ++i)
    count += dataset.GetRasterBand(i)->GetColorInterpretation() != GCI_AlphaBand;
  return count;
}

// A few bands' colours say what the file is; of many, a list of them says nothing more.
constexpr int kBandsNamed = 8;

// "3 bands (red, green, blue)"; "317 bands".
std::string describeBands(GDALDataset& dataset) {
  if (dataset.GetRasterCount() > kBandsNamed) return std::to_string(dataset.GetRasterCount()) + " bands";
  std::string names;
  for (int i = 1; i <= dataset.GetRasterCount(); ++i) {
    std::string name = GDALGetColorInterpretationName(dataset.GetRasterBand(i)->GetColorInterpretation());
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    names += (names.empty() ? "" : ", ") + name;
  }
  return std::to_string(dataset.GetRasterCount()) + " bands (" + names + ")";
}

// `dataset` as gdal_translate's `arguments` make it (`what` of it, for messages): a VRT in a file of GDAL's
// in-memory file system, which loader threads open again by name; the mask GDAL keeps (an alpha band's) goes
// with it.
ChosenBand translated(GDALDataset& dataset, std::vector<std::string> arguments, const std::string& what,
                      const SourceLocation& where) {
  static std::atomic<unsigned> made{0};
  const std::string file = dataset.GetDescription();
  auto memory = std::make_shared<const MemoryFile>("/vsimem/strata-" + std::to_string(made++) + "-of-" +
                                                   std::string(CPLGetFilename(file.c_str())) + ".vrt");
  arguments.insert(arguments.begin(), {"-of", "VRT"});
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  GDALTranslateOptions* options = GDALTranslateOptionsNew(argv.data(), nullptr);
  GDALDatasetH vrt = GDALTranslate(memory->path().c_str(), GDALDataset::ToHandle(&dataset), options, nullptr);
  GDALTranslateOptionsFree(options);
  if (!vrt) throw Error(where, "GDAL could not read " + what + " of '" + file + "': " + CPLGetLastErrorMsg());
  GDALClose(vrt);  // written out
  std::unique_ptr<GDALDataset> reopened(GDALDataset::Open(memory->path().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!reopened) throw Error(where, "GDAL could not read " + what + " of '" + file + "'");
  return {std::move(reopened), std::move(memory)};
}

// A normal map with its green band inverted, full scale to 0 (255 for 8-bit bands, 65535 for 16-bit).
ChosenBand greenInverted(GDALDataset& dataset, const SourceLocation& where) {
  const std::string full = dataset.GetRasterBand(2)->GetRasterDataType() == GDT_Byte ? "255" : "65535";
  return translated(dataset, {"-scale_2", "0", full, full, "0"}, "the green band", where);
}

}  // namespace

ChosenBand chooseBand(std::unique_ptr<GDALDataset> dataset, const BandOptions& options) {
  const std::string file = dataset->GetDescription();
  const std::string kind = toString(options.kind);
  if (readsThreeBands(options.kind)) {
    if (options.band != 0)
      throw Error(options.bandWhere, "a " + kind + " layer reads red, green and blue; `band` picks one band",
                  "remove `band`, or read one band as a one-channel kind (luminance, height, scalar, mask)");
    if (options.kind == LayerKind::Normal && valueBandCount(*dataset) < 3)
      throw Error(options.kindWhere,
                  "'" + file + "' has " + describeBands(*dataset) + "; a normal layer reads three: east, north, up",
                  "give a normal map of three bands, or read the band as a one-channel kind (height, scalar)");
    if (options.greenSouth) return greenInverted(*dataset, options.kindWhere);
    return {std::move(dataset), nullptr};
  }
  if (options.band == 0) {
    if (valueBandCount(*dataset) <= 1) return {std::move(dataset), nullptr};
    throw Error(options.kindWhere, "'" + file + "' has " + describeBands(*dataset) + "; a " + kind + " layer reads one",
                "give `band: 1` (or another, up to " + std::to_string(dataset->GetRasterCount()) +
                    ") to read that band, or `kind: color` to read the colours");
  }
  if (options.band > dataset->GetRasterCount())
    throw Error(options.bandWhere,
                "'" + file + "' has " + describeBands(*dataset) + ", no band " + std::to_string(options.band),
                "give a band from 1 to " + std::to_string(dataset->GetRasterCount()));
  if (dataset->GetRasterCount() == 1) return {std::move(dataset), nullptr};
  const std::string band = std::to_string(options.band);
  return translated(*dataset, {"-b", band}, "band " + band, options.bandWhere);
}

}  // namespace strata::gdal
