#pragma once
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include <benchmark/benchmark.h>

#include <strata/gl.hpp>
#include <strata/gl/context.hpp>
#include <strata/host/engine.hpp>

namespace strata::bench {

// The main of a benchmark that renders: one headless context for every configuration (each loads its own
// engine on it), the GPU's name printed and kept in the output's context as `gpu`, then Google Benchmark
// runs what `registerAll` registers.
inline int runHeadless(int argc, char** argv, const std::function<void()>& registerAll) {
  const auto context = createHeadlessContext(false);
  const std::string renderer = currentGlInfo().renderer;
  benchmark::AddCustomContext("gpu", renderer);
  std::printf("%s; %s\n", context->description().c_str(), renderer.c_str());
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Renders `frames` frames and waits for them: the first frames compile programs on use (and JIT them on llvmpipe).
inline void warmUp(Engine& engine, int width, int height, int frames) {
  for (int i = 0; i < frames; ++i) engine.render(width, height);
  glFinish();
}

// Renders one frame and waits for it with glFinish, so that the wall time holds the GPU's work: its ms.
inline double timedFrameMs(Engine& engine, int width, int height) {
  const auto start = std::chrono::steady_clock::now();
  engine.render(width, height);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Sets each counter to its total over the iterations divided by their number: means per frame.
inline void setMeans(benchmark::State& state, std::initializer_list<std::pair<const char*, double>> totals) {
  for (const auto& [name, total] : totals)
    state.counters[name] = benchmark::Counter(total, benchmark::Counter::kAvgIterations);
}

// Whether the environment variable `variable` asks for the reduced run ("reduced"): a few frames a
// configuration, for llvmpipe, where the full run's 300 would take hours.
inline bool reducedRun(const char* variable) {
  const char* choice = std::getenv(variable);
  return choice && std::string_view(choice) == "reduced";
}

// Registers `name`: `iterations` frames of `run(state, arguments...)`, each in real (wall) milliseconds, as every
// rendering benchmark times its frames.
template <class Run, class... Arguments>
void registerFrames(const std::string& name, int iterations, Run run, Arguments&&... arguments) {
  benchmark::RegisterBenchmark(name.c_str(), run, std::forward<Arguments>(arguments)...)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(iterations);
}

}  // namespace strata::bench
