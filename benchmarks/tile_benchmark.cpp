// strata-bench-tile (issue 3): `strata tile` against `gdal_translate -of COG` with overviews, on the same
// raster, reported as the ratio of their wall-clock times. The raster is $STRATA_BENCH_RASTER
// (scripts/bench.sh makes a 40000x20000 one); unset, an 8192x4096 one is made here so that the benchmark
// runs on its own.
#include <benchmark/benchmark.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace {

namespace fs = std::filesystem;

// One iteration takes a second (8192x4096) to about a minute (40000x20000, 2 cores): two show the spread.
constexpr int kIterations = 2;

// gdal_translate in process, with `arguments` as on its command line; the output is closed (so flushed)
// before this returns.
void gdalTranslate(const fs::path& input, const fs::path& output, const std::vector<std::string>& arguments) {
  CPLStringList argv;
  for (const std::string& argument : arguments) argv.AddString(argument.c_str());
  std::unique_ptr<GDALTranslateOptions, decltype(&GDALTranslateOptionsFree)> options(
      GDALTranslateOptionsNew(argv.List(), nullptr), GDALTranslateOptionsFree);
  CPLErrorReset();
  GDALDatasetH source = GDALOpen(input.c_str(), GA_ReadOnly);
  if (!source) throw std::runtime_error("GDAL cannot open '" + input.string() + "': " + CPLGetLastErrorMsg());
  GDALDatasetH written = GDALTranslate(output.c_str(), source, options.get(), nullptr);
  if (written) GDALClose(written);
  GDALClose(source);
  if (!written) throw std::runtime_error("GDAL could not write '" + output.string() + "': " + CPLGetLastErrorMsg());
}

// The stand-alone input: the Earth image the demo drapes (xplanet-images), enlarged to a global
// longitude/latitude GeoTIFF, tiled and compressed as scripts/make-test-data.sh writes its rasters.
fs::path makeInput(const fs::path& directory) {
  const fs::path input = directory / "earth-8192x4096.tif";
  gdalTranslate("/usr/share/xplanet/images/earth.jpg", input,
                {"-of", "GTiff", "-outsize", "8192", "4096", "-r", "bilinear", "-a_srs", "EPSG:4326", "-a_ullr", "-180",
                 "90", "180", "-90", "-co", "TILED=YES", "-co", "COMPRESS=DEFLATE"});
  return input;
}

double megapixelsOf(const fs::path& raster) {
  std::unique_ptr<GDALDataset> dataset(
      GDALDataset::Open(raster.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR));
  if (!dataset) throw std::runtime_error("GDAL cannot open '" + raster.string() + "': " + CPLGetLastErrorMsg());
  return 1e-6 * dataset->GetRasterXSize() * dataset->GetRasterYSize();
}

// Times `tile` writing `output` afresh each iteration; a failure ends the benchmark with its message.
void timeTiling(benchmark::State& state, const fs::path& output, double megapixels, const std::function<void()>& tile) {
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove(output);  // neither writer may find a file to update in place
    state.ResumeTiming();
    try {
      tile();
    } catch (const std::exception& error) {
      state.SkipWithError(error.what());
      break;
    }
  }
  state.counters["input_Mpx_per_s"] = benchmark::Counter(megapixels, benchmark::Counter::kIsIterationInvariantRate);
}

void strataTile(benchmark::State& state, const fs::path& input, const fs::path& output, double megapixels) {
  const strata::TilingRequest request{input, output, {}, true, {}};
  timeTiling(state, output, megapixels, [&] {
    strata::PluginRegistry plugins;  // each `strata tile` loads them: projections from plugins count
    plugins.loadDirectories(strata::defaultPluginDirectories());
    if (strata::tileRaster(plugins, request).reprojected)
      throw std::runtime_error(
          "strata tile reprojected the input and gdal_translate would not: give a raster in a "
          "projection Strata samples directly, e.g. longitude/latitude");
  });
}

// issue 3's command line, with the creation options core/tiling/src/tile_raster.cpp passes, so that both
// write the same file. strata tile also sets GDAL_NUM_THREADS while it translates (docs/benchmarks.md).
void gdalTranslateCog(benchmark::State& state, const fs::path& input, const fs::path& output, double megapixels) {
  const std::vector<std::string> arguments{"-of", "COG",
                                           "-co", "BLOCKSIZE=512",
                                           "-co", "COMPRESS=DEFLATE",
                                           "-co", "OVERVIEWS=IGNORE_EXISTING",
                                           "-co", "RESAMPLING=AVERAGE",
                                           "-co", "NUM_THREADS=ALL_CPUS",
                                           "-co", "BIGTIFF=IF_SAFER"};
  timeTiling(state, output, megapixels, [&] { gdalTranslate(input, output, arguments); });
}

// The console report, remembering each benchmark's best wall-clock time for the ratio.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // Colour only on a terminal, as the library's own reporter does, so that logs stay plain text.
  RatioReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
      double& best = bestSeconds_.try_emplace(run.run_name.function_name, run.GetAdjustedRealTime()).first->second;
      best = std::min(best, run.GetAdjustedRealTime());
    }
  }

  void printRatio() const {
    const auto strata = bestSeconds_.find("strata_tile"), gdal = bestSeconds_.find("gdal_translate_cog");
    if (strata == bestSeconds_.end() || gdal == bestSeconds_.end()) return;  // filtered out, or failed
    std::printf("strata tile / gdal_translate -of COG: %.2f\n", strata->second / gdal->second);
  }

 private:
  std::map<std::string, double> bestSeconds_;  // both in seconds: the benchmarks' unit
};

void runBenchmarks(const fs::path& scratch) {
  const char* given = std::getenv("STRATA_BENCH_RASTER");
  const fs::path input = given && *given ? fs::path(given) : makeInput(scratch);
  const double megapixels = megapixelsOf(input);
  std::printf("input: %s (%.1f megapixels)\n", input.c_str(), megapixels);
  for (auto* benchmark :
       {benchmark::RegisterBenchmark("strata_tile", strataTile, input, scratch / "strata.tif", megapixels),
        benchmark::RegisterBenchmark("gdal_translate_cog", gdalTranslateCog, input, scratch / "gdal.tif", megapixels)})
    benchmark->UseRealTime()->Unit(benchmark::kSecond)->Iterations(kIterations);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.printRatio();
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  GDALAllRegister();
  const fs::path scratch = fs::temp_directory_path() / ("strata-bench-tile-" + std::to_string(getpid()));
  fs::create_directories(scratch);
  int status = 0;
  try {
    runBenchmarks(scratch);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "strata-bench-tile: error: %s\n", error.what());
    status = 1;
  }
  fs::remove_all(scratch);  // the outputs are as large as the input
  benchmark::Shutdown();
  return status;
}
