// strata-make-test-data: writes the procedural planet (the demonstration data of [Kooima 2008, ch. 4]) "observed"
// through several projections and resolutions, as GeoTIFFs for the tests and benchmarks. Positions come from PROJ,
// heights and colours from the planet model, nothing from Strata.
#include <gdal_priv.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "ice_sheet.hpp"
#include "observation.hpp"
#include "observation_writer.hpp"
#include "panchromatic.hpp"
#include "seasons.hpp"

namespace {

// "WIDTHxHEIGHT", or an explanation of what is wrong with it.
std::string parseSize(const std::string& text, int& width, int& height) {
  char separator = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &separator, &height, &rest) != 3 || separator != 'x' || width < 2 ||
      height < 1)
    return "expected WIDTHxHEIGHT, e.g. 40000x20000";
  return {};
}

void makeTestData(const std::filesystem::path& directory, int largeWidth, int largeHeight) {
  using namespace strata::testdata;
  GDALAllRegister();
  std::filesystem::create_directories(directory);
  const strata::procedural::PlanetModel planet({}, kMarsRadius);
  const bool progress = isatty(STDOUT_FILENO);
  if (largeWidth > 0) {
    const Observation large = largeGlobalObservation(largeWidth, largeHeight);
    writeObservation(large, planet, directory, Products::ColourOnly, progress);
    return;
  }
  for (const Observation& observation : standardObservations())
    writeObservation(observation, planet, directory, Products::HeightAndColour, progress);
  writeObservation(galeStrip(), strata::procedural::PlanetModel(finePlanetParameters(), kMarsRadius), directory,
                   Products::HeightAndColour, progress);
  writeSeasons(directory);
  writeIceSheet(directory);
  writePanchromatic(directory);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Writes GeoTIFFs of the procedural planet (Mars-sized) observed through several projections: "
      "global, north, south, healpix, strip and gale (25 cm texels at 137.4 E, 4.6 S), each as <name>-height.tif "
      "and <name>-color.tif, and twelve months "
      "of the global one with seasonal snow, season-200401-color.tif to season-200412-color.tif, an ice sheet over "
      "the north pole, ice-height.tif and ice-color.tif, and a panchromatic view of the strip, strip-luminance.tif."};
  std::string directory;
  int largeWidth = 0, largeHeight = 0;
  app.add_option("directory", directory, "where the GeoTIFFs go (made if missing)")->required();
  app.add_option_function<std::string>(
      "--large",
      [&](const std::string& text) {
        if (std::string problem = parseSize(text, largeWidth, largeHeight); !problem.empty())
          throw CLI::ValidationError("--large", problem);
      },
      "write only a global longitude/latitude colour raster of WIDTHxHEIGHT pixels (for benchmarks)");
  CLI11_PARSE(app, argc, argv);
  try {
    makeTestData(directory, largeWidth, largeHeight);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "strata-make-test-data: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
