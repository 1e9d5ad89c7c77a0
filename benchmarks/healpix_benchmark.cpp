// strata-bench-healpix: geometry.healpix's frame time against its detail threshold (vertices wanted per
// pixel), at the paper's 1024x768, so that it can be read beside the paper's figures
// ([Westerteiger et al. 2011, §4, Fig. 7]: thresholds 0.005, 0.01, 0.2 and 1.0 gave 105, 75, 24 and 9 fps,
// shaded DEM). The planet is source.procedural's on a Mars-sized body, unexaggerated, seen whole from orbit
// and near the ground at a steep angle (procedural_mars_pipeline.hpp). Then the near view over heights from a
// longitude/latitude raster and from the HEALPix pyramid `strata tile --to healpix` makes of it: the same
// terrain, its nodes bounded by one global range or by the pyramid's page ranges.
// STRATA_BENCH_HEALPIX=reduced times fewer frames, for llvmpipe; unset, the full set (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gdal_priv.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <strata/gl.hpp>
#include <strata/host/engine.hpp>
#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "headless_main.hpp"
#include "procedural_mars_pipeline.hpp"

namespace {

namespace fs = std::filesystem;

// The paper's window and thresholds.
constexpr int kWidth = 1024, kHeight = 768;
const std::vector<std::string> kThresholds = {"0.005", "0.01", "0.2", "1.0"};

// The first frames compile programs on use and JIT them on llvmpipe; the selection itself is stateless,
// so a frame is typical from the second on.
constexpr int kWarmUpFrames = 2;

struct Scene {
  std::string name;
  strata::Camera camera;
};

// One configuration: the pipeline loaded once with the threshold (as `--set` would), warmed up, then one
// frame per iteration, waited for with glFinish so that the wall time holds the GPU's work (on llvmpipe the
// timer query does not). Counters are means per frame.
void benchmarkHealpix(benchmark::State& state, const fs::path& pipeline, const Scene& scene,
                      const std::string& threshold) {
  strata::Engine engine;
  engine.load(pipeline, {"nodes.terrain.threshold=" + threshold});
  engine.camera() = scene.camera;
  strata::bench::warmUp(engine, kWidth, kHeight, kWarmUpFrames);
  double frameMs = 0, visibilityMs = 0, rasterMs = 0, nodes = 0, vertices = 0;
  for (auto _ : state) {
    frameMs += strata::bench::timedFrameMs(engine, kWidth, kHeight);
    const strata::GeometryStatistics geometry = engine.geometryStatistics();
    visibilityMs += geometry.visibilityMs, rasterMs += geometry.rasterisationMs;
    nodes += geometry.patches, vertices += double(geometry.vertices);
  }
  // vertices_per_pixel: what the threshold asks for, to set beside it: every vertex of every node drawn, off screen
  // or not.
  strata::bench::setMeans(state, {{"frame_ms", frameMs},
                                  {"visibility_ms", visibilityMs},
                                  {"raster_ms", rasterMs},
                                  {"nodes", nodes},
                                  {"vertices", vertices},
                                  {"vertices_per_pixel", vertices / (double(kWidth) * kHeight)}});
  state.counters["fps"] = double(state.iterations()) * 1000.0 / frameMs;  // the paper's unit; from the wall time
}

// A smooth field on Mars (m), +-5.5 km over wavelengths of 50 to 120 degrees, as a global 4096 x 2048
// longitude/latitude raster.
void writeFieldRaster(const fs::path& raster) {
  constexpr int width = 4096, height = 2048;
  GDALAllRegister();
  std::unique_ptr<GDALDataset> dataset(
      GetGDALDriverManager()->GetDriverByName("GTiff")->Create(raster.c_str(), width, height, 1, GDT_Float32, nullptr));
  OGRSpatialReference mars;
  mars.SetFromUserInput("+proj=longlat +R=3396190");
  dataset->SetSpatialRef(&mars);
  std::array<double, 6> geotransform{-180.0, 360.0 / width, 0.0, 90.0, 0.0, -180.0 / height};
  dataset->SetGeoTransform(geotransform.data());
  std::vector<float> row(width);
  for (int y = 0; y < height; ++y) {
    const double lat = (90.0 - (y + 0.5) * 180.0 / height) * std::numbers::pi / 180.0;
    for (int x = 0; x < width; ++x) {
      const double lon = (-180.0 + (x + 0.5) * 360.0 / width) * std::numbers::pi / 180.0;
      row[std::size_t(x)] = float(4000.0 * std::sin(3.0 * lon + 1.0) * std::cos(2.0 * lat) +
                                  1500.0 * std::sin(7.0 * lon) * std::sin(5.0 * lat + 0.3));
    }
    if (dataset->GetRasterBand(1)->RasterIO(GF_Write, 0, y, width, 1, row.data(), width, 1, GDT_Float32, 0, 0) !=
        CE_None)
      throw std::runtime_error("cannot write " + raster.string());
  }
}

// The field's raster and the HEALPix pyramid of nside 1024 (pages of 1,700 km) that strata tile makes of it;
// returns the pipelines over each, in that order, with procedural.yaml's global range of +-12 km.
std::vector<fs::path> writeFieldPipelines() {
  const fs::path scratch = fs::temp_directory_path();
  const fs::path raster = scratch / "strata-bench-healpix-field.tif",
                 pyramid = scratch / "strata-bench-healpix-pyramid.tif";
  writeFieldRaster(raster);
  strata::tileRaster(strata::PluginRegistry(),
                     {.input = raster, .output = pyramid, .target = "healpix", .overwrite = true, .nside = 1024});
  std::vector<fs::path> pipelines;
  for (const fs::path& heights : {raster, pyramid}) {
    pipelines.push_back(scratch / ("strata-bench-healpix-" + heights.stem().string() + ".yaml"));
    std::ofstream(pipelines.back())
        << "strata: 1\nbody: {name: Mars, radius: 3396190}\nnodes:\n"
           "  colours: {type: source.procedural, kind: color}\n"
           "  relief: {type: source.gdal, kind: height, path: "
        << heights.string()
        << "}\n"
           "  terrain: {type: geometry.healpix, height: relief, lowest: -12000, highest: 12000}\n"
           "  frame: {type: output.image, geometry: terrain, surface: [colours]}\n";
  }
  return pipelines;
}

// Every threshold from both views. The full set times 300 frames each (minutes on a GPU); the reduced one,
// for llvmpipe where a fine frame takes seconds, times 3 and leaves out the near view at threshold 1.0 (30
// million vertices, some 36 s a frame on 2 cores), the whole run within about 3 minutes.
void registerBenchmarks(const fs::path& pipeline) {
  const bool reduced = strata::bench::reducedRun("STRATA_BENCH_HEALPIX");
  const std::vector<Scene> scenes = {{"whole", strata::bench::wholeMarsView()},
                                     {"near", strata::bench::nearMarsView()}};
  for (const Scene& scene : scenes)
    for (const std::string& threshold : kThresholds) {
      if (reduced && scene.name == "near" && threshold == "1.0") continue;
      strata::bench::registerFrames("healpix/view:" + scene.name + "/threshold:" + threshold, reduced ? 3 : 300,
                                    benchmarkHealpix, pipeline, scene, threshold);
    }
  const std::vector<fs::path> field = writeFieldPipelines();
  for (std::size_t i = 0; i < field.size(); ++i)
    for (const std::string& threshold : {std::string("0.01"), std::string("0.2")}) {
      strata::bench::registerFrames(
          std::string("healpix/heights:") + (i == 0 ? "raster" : "pyramid") + "/view:near/threshold:" + threshold,
          reduced ? 3 : 300, benchmarkHealpix, field[i], Scene{"near", strata::bench::nearMarsView()}, threshold);
    }
}

}  // namespace

int main(int argc, char** argv) {
  return strata::bench::runHeadless(argc, argv, [] {
    registerBenchmarks(strata::bench::writeProceduralMarsPipeline("strata-bench-healpix", "geometry.healpix"));
  });
}
