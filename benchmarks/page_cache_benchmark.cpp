// Page-cache throughput (issue 3, docs/benchmarks.md): pages per second from a raster on disk (a COG from
// `strata tile`) to the GPU, through source.gdal and the page cache, as the view flies low over the
// planet; and the process's peak memory beside the cache's budget, for budgets of 64 and 256 MiB.
//   STRATA_BENCH_COG  the tiled raster (scripts/bench.sh makes a 40000x20000 one); required
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <strata/gl/context.hpp>
#include <strata/host/engine.hpp>

namespace {

namespace fs = std::filesystem;

constexpr int kFrame = 1280, kFrameHeight = 720;

// Resident memory now, MiB: the second field of /proc/self/statm, in pages. Sampled after each frame,
// it gives each run's own peak, which the process-wide ru_maxrss cannot once an earlier run has set it.
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long total = 0, resident = 0;
  statm >> total >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / double(1 << 20);
}

std::string environment(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

fs::path writePipeline(const fs::path& raster, int budgetMiB) {
  const fs::path file = fs::temp_directory_path() / "strata-bench-page-cache.yaml";
  std::ofstream(file) << "strata: 1\n"
                         "camera: {lon: 0, lat: 0, altitude: 300000, tilt: 30}\n"
                         "cache: {budget: "
                      << budgetMiB
                      << "}\n"
                         "nodes:\n"
                         "  imagery: {type: source.gdal, path: '"
                      << raster.string()
                      << "', kind: color}\n"
                         "  globe: {type: geometry.icosahedral}\n"
                         "  frame: {type: output.image, geometry: globe, surface: [imagery]}\n";
  return file;
}

// Flies along the equator and back up a meridian, 300 km up, each view rendered until every page it
// wants is loaded: every step needs pages the last did not.
void BM_PageCacheThroughput(benchmark::State& state) {
  const std::string raster = environment("STRATA_BENCH_COG", "");
  if (raster.empty()) {
    state.SkipWithError("set STRATA_BENCH_COG to a raster tiled by strata tile (scripts/bench.sh makes one)");
    return;
  }
  const int budgetMiB = int(state.range(0));
  auto context = strata::createHeadlessContext(false);
  strata::Engine engine;
  const double baselineMiB = residentMiB();
  double peakMiB = baselineMiB;
  engine.load(writePipeline(raster, budgetMiB));
  std::uint64_t pages = 0;
  for (auto _ : state) {
    const std::uint64_t before = engine.pageCacheStatistics().uploaded;
    for (int step = 0; step < 24; ++step) {
      engine.camera().lon = -170.0 + 15.0 * step;
      engine.camera().lat = step < 12 ? 0.0 : 6.0 * (step - 12);
      engine.renderComplete(kFrame, kFrameHeight);
      peakMiB = std::max(peakMiB, residentMiB());
    }
    pages += engine.pageCacheStatistics().uploaded - before;
  }
  const strata::PageCacheStatistics& cache = engine.pageCacheStatistics();
  state.counters["pages_per_s"] = benchmark::Counter(double(pages), benchmark::Counter::kIsRate);
  state.counters["capacity_pages"] = cache.capacity;
  state.counters["evicted"] = double(cache.evicted);
  state.counters["budget_MiB"] = budgetMiB;
  state.counters["cache_MiB"] = double(cache.gpuBytes + cache.stagingBytes) / (1 << 20);
  state.counters["peak_rss_MiB"] = peakMiB;
  state.counters["rss_growth_MiB"] = peakMiB - baselineMiB;
  std::printf("%s: %s\n", raster.c_str(), strata::currentGlInfo().renderer.c_str());
}

// 64 MiB: a cache far smaller than the view's working set, which must evict within each step's flight;
// 256 MiB: the pipeline default.
BENCHMARK(BM_PageCacheThroughput)
    ->ArgName("budget_MiB")
    ->Arg(64)
    ->Arg(256)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
