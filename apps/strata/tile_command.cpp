#include <unistd.h>

#include <cstdio>
#include <memory>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

// A one-line percentage on a terminal; nothing when output goes to a file or a pipe.
std::function<void(double)> terminalProgress() {
  if (!isatty(STDERR_FILENO)) return {};
  return [last = -1](double fraction) mutable {
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last) return;
    last = percent;
    std::fprintf(stderr, "\rstrata tile: %3d%%%s", percent, percent >= 100 ? "\n" : "");
  };
}

void tile(TilingRequest request) {
  PluginRegistry plugins;
  plugins.loadDirectories(defaultPluginDirectories());  // projections from plugins count as registered
  request.progress = terminalProgress();
  const TilingResult result = tileRaster(plugins, request);
  if (result.nside != 0)
    std::printf("strata: wrote %s (%dx%d, %d overviews, a HEALPix pyramid of nside %lld (NESTED) on %s)\n",
                request.output.c_str(), result.width, result.height, result.overviews,
                static_cast<long long>(result.nside), result.crs.c_str());
  else
    std::printf("strata: wrote %s (%dx%d, %d overviews, %s%s)\n", request.output.c_str(), result.width, result.height,
                result.overviews, result.reprojected ? "reprojected to " : "", result.crs.c_str());
}

}  // namespace

void addTileCommand(CLI::App& app, int& exitCode) {
  auto request = std::make_shared<TilingRequest>();
  CLI::App* command = app.add_subcommand(
      "tile", "turn any GDAL raster into the tiled pyramid Strata pages from (a Cloud Optimized GeoTIFF)");
  command->add_option("input", request->input, "the raster to tile")->required();
  command->add_option("output", request->output, "the .tif to write")->required();
  command->add_option("--to", request->target,
                      "reproject into: equirectangular, polar-north, polar-south, a CRS (PROJ string, EPSG:code, WKT), "
                      "or healpix: a HEALPix pyramid (NESTED faces side by side; the plane is +proj=healpix); default: "
                      "keep a CRS Strata samples directly, else the best-suited projection");
  command->add_option("--nside", request->nside,
                      "with --to healpix: the faces' resolution, a power of two from 512 to 2^30 (above 2^26, a "
                      "window of the one face the input covers); default: the least whose texels are no larger than "
                      "the input's");
  command->add_flag("--overwrite", request->overwrite, "replace the output if it exists");
  command->callback([request, &exitCode] { exitCode = reportingErrors([&] { tile(*request); }); });
}

}  // namespace strata::cli
